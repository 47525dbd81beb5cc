#pragma once
// The presets as glTF 2.0 materials (a .gltf JSON file holding only materials).
#include <string>
#include <vector>

#include "analysis/presets/shading_presets.h"
#include "analysis/study/study.h"

namespace fl::documents {

// glTF's colours are linear Rec.709 (sRGB primaries, D65): colours in any other working space are
// converted with OpenColorIO's matrix (asset.extras say so), and the ΔE2000 of a stored colour is
// measured in the working space. Metals: baseColorFactor = F0,
// metallicFactor 1. Dielectrics: metallicFactor 0, KHR_materials_ior with the index of
// analysis::ShadingPreset, KHR_materials_specular's specularColorFactor = F0 / ((η − 1)/(η + 1))²
// when that differs from white by more than kSpecularColorMin in a channel, and
// KHR_materials_transmission (factor 1, white base colour) when clear; opaque ones have a black
// base colour (no diffuse). A factor outside [0, 1] is stored through analysis::into_unit_range;
// each material's extras give the true value, the out_of_range list and the ΔE2000 the stored
// colour costs at normal incidence. Every material's extras also state its data source, coverage
// (n and k, each alone), whether it is extrapolated and where (asset.extras explain these), a
// consensus' pages and spread, and what a short name resolved to. Every material has
// roughnessFactor options.roughness; asset.extras list the materials a glob skipped.
inline constexpr double kSpecularColorMin = 1e-3;
std::string presets_gltf(const analysis::Context& ctx,
                         const std::vector<analysis::MaterialStudy>& studies,
                         const analysis::ExportOptions& options = {});

}  // namespace fl::documents
