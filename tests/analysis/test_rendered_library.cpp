// Rendered error over the library (analysis/library/rendered_library.h).
#include <gtest/gtest.h>

#include <cstdio>

#include "analysis/library/rendered_library.h"
#include "analysis/lut/lut_accuracy.h"
#include "analysis/pipeline/materials.h"
#include "fresnel/registry.h"

namespace fl::analysis {
namespace {

size_t shader_index(const std::string& name) {
  const auto& s = library_shaders();
  for (size_t i = 0; i < s.size(); ++i)
    if (s[i].name == name) return i;
  throw std::logic_error("no shader " + name);
}

// 101 metal pages whose every shader renders at page/100 (IBL) and 2·page/100 (area), but basis4
// one point worse than F82 on the last 3 pages: the nearest-rank statistics are known exactly.
TEST(RenderedLibrary, RowsAreNearestRankStatisticsOfThePages) {
  RenderedLibrary lib;
  const size_t shaders = library_shaders().size(), f82 = shader_index("f82"),
               basis4 = shader_index("basis4");
  for (int p = 0; p <= 100; ++p) {
    lib.pages.push_back("page" + std::to_string(p));
    lib.classes.push_back(spectral::MaterialClass::Metal);
    lib.rms.push_back(std::vector<std::array<double, 2>>(shaders, {p / 100.0, 2 * p / 100.0}));
    if (p >= 98) lib.rms.back()[basis4] = {lib.rms.back()[f82][0] + 1, lib.rms.back()[f82][1]};
  }
  const auto rows = rendered_library_rows(lib, GpuCosts{});
  const RenderedLibraryRow* ibl = nullptr;
  const RenderedLibraryRow* area = nullptr;
  for (const auto& r : rows) {
    EXPECT_NE(r.page_class, "dielectric");  // no dielectric page, no row
    if (r.page_class == "metal" && r.shader->name == "f82")
      (r.lighting == Lighting::Ibl ? ibl : area) = &r;
    if (r.page_class == "all" && r.shader->name == "basis4") {
      EXPECT_EQ(r.worse_than_f82, r.lighting == Lighting::Ibl ? 3 : 0);
      if (r.lighting == Lighting::Ibl)
        EXPECT_EQ(r.worst_pages,
                  (std::vector<std::string>{"page100", "page99", "page98", "page97", "page96"}));
    }
  }
  ASSERT_TRUE(ibl && area);
  EXPECT_EQ(ibl->pages, 101);
  EXPECT_DOUBLE_EQ(ibl->median, 0.50);
  EXPECT_DOUBLE_EQ(ibl->p90, 0.90);
  EXPECT_DOUBLE_EQ(ibl->p99, 0.99);
  EXPECT_DOUBLE_EQ(ibl->max, 1.00);
  EXPECT_DOUBLE_EQ(area->median, 1.00);
  EXPECT_FALSE(ibl->gpu.has_value());  // no cost file: unmeasured
}

// On gold, the library's per-page errors (each shader's weights on the table terms) equal
// lut-accuracy's (each model shaded through its own unit) for the derived sets.
TEST(RenderedLibrary, GoldMatchesLutAccuracy) {
  Settings settings;
  settings.paths = {FL_DEFAULT_DB, FL_MATERIALS};
  const Context ctx(settings);
  const auto set = load_materials(ctx, {"gold"}, {});
  const auto points = lut_accuracy_points();
  const auto lib = rendered_library(ctx, set.materials, points);
  ASSERT_EQ(lib.pages.size(), 1u);
  StudyOptions options;
  options.fit = false;
  const auto study = study_materials(ctx, set.materials, options).front();
  const auto truth = lobe_truth(ctx, set.materials.front(), points);
  for (const char* name : {"schlick", "f82", "basis3", "basis4", "basis5"}) {
    const auto m = fresnel::model_from_name(name).model;
    const auto& p = study.result(m).derived;
    EXPECT_NEAR(lib.rms[0][shader_index(name)][0],
                error_stats(rendered_de00(ctx, truth, m, p, Lighting::Ibl, points)).rms, 1e-12)
        << name;
    EXPECT_NEAR(lib.rms[0][shader_index(name)][1],
                error_stats(rendered_de00(ctx, truth, m, p, Lighting::Area, points)).rms, 1e-12)
        << name;
  }
  // basis2, gold's curve projected on the basis's first two functions {1, b1}, renders it better
  // than Schlick's F0 (measured 0.231 against 0.567 under IBL).
  std::printf("gold under IBL: basis2 %.3f, schlick %.3f\n", lib.rms[0][shader_index("basis2")][0],
              lib.rms[0][shader_index("schlick")][0]);
  EXPECT_LT(lib.rms[0][shader_index("basis2")][0], lib.rms[0][shader_index("schlick")][0]);
  // Fitted to the render, F82 renders no worse than its derived start.
  EXPECT_LE(
      lib.rms[0][shader_index("f82 rendered")][0] + lib.rms[0][shader_index("f82 rendered")][1],
      lib.rms[0][shader_index("f82")][0] + lib.rms[0][shader_index("f82")][1] + 1e-12);
}

}  // namespace
}  // namespace fl::analysis
