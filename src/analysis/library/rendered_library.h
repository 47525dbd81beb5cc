#pragma once
// Rendered error over the whole database against the number of table terms K and the GPU cost:
// every page `library --class all` keeps, shaded by the pre-integrated models an engine can ship
// (Schlick, F82 derived and fitted to the render, the basis at K = 2..5) under IBL and area lights
// at lut-accuracy's shading points, against brute-force spectral integration of the lobe.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "analysis/lut/rendered.h"
#include "analysis/speed/speed.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// A shader an engine can ship: a pre-integrated model with a parameter set, or (no model) the
// ground-truth curve projected on the basis's first `terms` terms.
struct LibraryShader {
  std::string name;  // schlick, f82, f82 rendered, basis2 … basis5
  std::optional<fresnel::Model> model;
  ParameterSet set = ParameterSet::Derived;
  int terms = 0;  // K: table terms the shader weighs
};
const std::vector<LibraryShader>& library_shaders();

struct RenderedLibrary {
  std::vector<std::string> pages;
  std::vector<spectral::MaterialClass> classes;
  // rms[page][shader]: RMS ΔE2000 over the shading points under {ibl, area}.
  std::vector<std::vector<std::array<double, 2>>> rms;
};
// Every page of `materials` (loaded as `library --class all` loads the database).
RenderedLibrary rendered_library(const Context& ctx, const std::vector<LoadedMaterial>& materials,
                                 const std::vector<ShadingPoint>& points);

// One shader × lighting × class (all, metal, dielectric): the distribution of the pages' RMS.
struct RenderedLibraryRow {
  const LibraryShader* shader = nullptr;
  Lighting lighting = Lighting::Ibl;
  std::string page_class;  // all | metal | dielectric
  std::optional<GpuCost> gpu;
  int pages = 0, worse_than_f82 = 0;             // pages where it renders worse than F82 derived
  double median = 0, p90 = 0, p99 = 0, max = 0;  // nearest rank (util/quantile.h)
  // The tail by name: the kWorstPages worst pages, worst first, and their RMS.
  std::vector<std::string> worst_pages;
  std::vector<double> worst_values;
};
inline constexpr size_t kWorstPages = 5;
std::vector<RenderedLibraryRow> rendered_library_rows(const RenderedLibrary& lib,
                                                      const GpuCosts& gpu);
Table rendered_library_table(const Context& ctx, const RenderedLibrary& lib,
                             const std::vector<RenderedLibraryRow>& rows);

}  // namespace fl::analysis
