#pragma once
// The presets as a MaterialX 1.39 document, in one of three shading models.
#include <string>
#include <vector>

#include "analysis/presets/shading_presets.h"
#include "analysis/study/study.h"
#include "color/matrix.h"

namespace fl::documents {

// generalized_schlick: one generalized_schlick_bsdf per material (color0 = F0, color82 = the F82
// tint, color90 = 1; scatter_mode RT for clear dielectrics) under a `surface`.
// open_pbr_surface: analysis::open_pbr_parameters. standard_surface: metals through Gulbrandsen's
// artistic IOR (base_color = F0 as reflectivity, specular_color = the edge tint g, metalness 1);
// dielectrics metalness 0, specular_IOR η, transmission 1 when clear, base 0 when opaque.
enum class MaterialxShader { GeneralizedSchlick, OpenPbrSurface, StandardSurface };
MaterialxShader materialx_shader_from_name(const std::string& name);  // InputError for others
const char* to_string(MaterialxShader s);

// The colour space a document's values are in: MaterialX 1.39's name for it and the matrix from
// the working space. MaterialX's colour management knows acescg, lin_rec709 and lin_displayp3 (=
// our lin_p3d65) among linear spaces; values in any other working space (aces2065-1, lin_rec2020,
// an OCIO space that is none of these) are converted to acescg through OpenColorIO, and `note` says
// so.
struct MaterialxSpace {
  std::string name;
  color::Mat3 from_working;
  std::string note;
};
MaterialxSpace materialx_space(const analysis::Context& ctx);

// Every material of `studies` as a surfacematerial; each carries a `doc` attribute with its data
// source, its coverage (n and k, each alone), whether it is extrapolated and where, a consensus'
// pages and spread, what a short name resolved to, and its out_of_range list with the colours
// stored in [0, 1] instead (analysis/presets/shading_presets.h). The document's comment explains
// these and counts the extrapolated materials.
std::string presets_materialx(const analysis::Context& ctx,
                              const std::vector<analysis::MaterialStudy>& studies,
                              MaterialxShader shader, const analysis::ExportOptions& options = {});

}  // namespace fl::documents
