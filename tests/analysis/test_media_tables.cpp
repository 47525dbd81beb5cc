// The blend, gamut, external-medium and internal-reflection tables (analysis/media_tables.h).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/media_tables.h"
#include "analysis/tables.h"
#include "fresnel/models.h"
#include "spectral/errors.h"

namespace fl::analysis {
namespace {

// Linear models commute with linear operations up to rounding.
constexpr double kLinearModelDe = 1e-9;
constexpr double kExact = 1e-12;

struct Catalog {
  Context ctx{[] {
    Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  std::vector<LoadedMaterial> materials = load_catalog(ctx);
  std::vector<MaterialStudy> studies = [this] {
    StudyOptions o;
    o.fit = false;  // these tables use derived parameters
    return study_materials(ctx, materials, o);
  }();
};

const Catalog& catalog() {
  static const Catalog c;
  return c;
}

size_t column(const Table& t, const std::string& name) {
  for (size_t i = 0; i < t.columns.size(); ++i)
    if (t.columns[i].name == name) return i;
  ADD_FAILURE() << "no column " << name << " in " << t.name;
  return 0;
}

TEST(Blend, LinearModelsBlendExactlyAndGulbrandsenDoesNot) {
  const auto& c = catalog();
  const Table t = blend_models_table(c.ctx, c.studies, {});
  ASSERT_EQ(t.rows.size(), 91u);  // 14 metals choose 2
  for (const char* linear : {"schlick", "f82", "lazanyi"}) {
    const size_t k = column(t, linear);
    for (const auto& row : t.rows) EXPECT_LE(std::get<double>(row[k]), kLinearModelDe) << linear;
  }
  const Table g = blend_table(c.ctx, c.studies, {});
  ASSERT_EQ(g.columns[0].name, "material_a");
  const double worst = std::get<double>(g.rows.front()[2]);
  std::printf("worst Gulbrandsen blend: %s + %s = %.3f\n", std::get<std::string>(g.rows[0][0]).c_str(),
              std::get<std::string>(g.rows[0][1]).c_str(), worst);
  // The talk: the worst pairs land around 1.5-2.5 ΔE2000.
  EXPECT_GE(worst, 1.5);
  EXPECT_LE(worst, 2.5);
  for (size_t i = 1; i < g.rows.size(); ++i)
    EXPECT_GE(std::get<double>(g.rows[i - 1][2]), std::get<double>(g.rows[i][2])) << "largest first";
}

TEST(Blend, WeightsAndChains) {
  const auto& c = catalog();
  BlendOptions o;
  o.weight = 0.0;  // nothing of the second material: A and B coincide for every model
  for (const auto& row : blend_models_table(c.ctx, c.studies, o).rows)
    for (size_t k = 2; k < row.size(); ++k) EXPECT_LE(std::get<double>(row[k]), kLinearModelDe);
  o.weight = 0.5;
  o.chain = 3;
  const Table t = blend_models_table(c.ctx, c.studies, o);
  EXPECT_EQ(t.rows.size(), 14u);
  for (const auto& row : t.rows) EXPECT_LE(std::get<double>(row[column(t, "schlick")]), kLinearModelDe);
  o.chain = 1;
  EXPECT_THROW(blend_table(c.ctx, c.studies, o), InputError);
}

TEST(Gamut, SchlickAndF82ConvertExactly) {
  const auto& c = catalog();
  const Table t = gamut_models_table(c.ctx, c.studies);
  ASSERT_EQ(t.rows.size(), 56u);  // 28 materials × 2 targets
  for (const char* linear : {"schlick", "f82"}) {
    const size_t k = column(t, linear);
    for (const auto& row : t.rows) EXPECT_LE(std::get<double>(row[k]), kLinearModelDe) << linear;
  }
  const Table g = gamut_table(c.ctx, c.studies);
  EXPECT_EQ(g.columns[1].name, "rec709");
  EXPECT_EQ(g.columns[2].name, "ap0");
  double worst = 0;
  for (const auto& row : g.rows) worst = std::max(worst, std::get<double>(row[2]));
  EXPECT_GT(worst, 0.5) << "Gulbrandsen's parameters do not convert like colours";
}

TEST(Media, OwnIndexHasNoReflectionAndAirMatchesSchlickTable) {
  const auto& c = catalog();
  // Through the general path: Tourmaline (constant 1.64) in a medium of index 1.64.
  for (const auto& m : c.materials)
    if (m.material.key == "tourmaline")
      for (const auto& rgb : ground_truth_curve(c.ctx, m.ior, 1.64)) {
        EXPECT_EQ(rgb.r, 0.0);
        EXPECT_EQ(rgb.g, 0.0);
        EXPECT_EQ(rgb.b, 0.0);
      }
  const Table t = media_table(c.ctx, c.studies);
  const Table s = schlick_table(c.ctx, c.materials);
  const size_t medium = column(t, "medium"), sym = column(t, "symmetric"), max_r = column(t, "exact_max_reflectance");
  int own = 0;
  for (const auto& row : t.rows) {
    const auto& m = std::get<std::string>(row[medium]);
    if (m == "own index") {
      EXPECT_EQ(std::get<double>(row[max_r]), 0.0) << std::get<std::string>(row[0]);
      ++own;
    }
    if (m == "air") {
      for (const auto& srow : s.rows)
        if (srow[0] == row[0]) EXPECT_NEAR(std::get<double>(row[sym]), std::get<double>(srow[3]), kExact);
    }
  }
  EXPECT_EQ(own, 14);
}

TEST(Internal, NormalIncidenceAndCriticalAngle) {
  const auto& c = catalog();
  for (const auto& st : c.studies) {
    if (st.material->material.material_class == spectral::MaterialClass::Metal) continue;
    spectral::ComplexIorSpectrum inverse = st.material->ior;
    for (auto& v : inverse.ior) v = {1.0 / v.real(), 0.0};
    const color::Rgb exact = ground_truth_rgb(c.ctx, inverse, 1.0, 1.0);
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(exact[ch], fresnel::schlick_internal(1.0, st.derived.f0[ch]), kExact) << st.material->material.name;
  }
  const Table t = internal_table(c.ctx, c.studies);
  ASSERT_EQ(t.rows.size(), 14u);
  for (const auto& row : t.rows) {
    EXPECT_NEAR(std::get<double>(row[column(t, "de00_normal")]), 0.0, 1e-9);
    EXPECT_NEAR(std::get<double>(row[column(t, "exact_at_critical")]), 1.0, kExact) << std::get<std::string>(row[0]);
    EXPECT_NEAR(std::get<double>(row[column(t, "schlick_at_critical")]), 1.0, kExact) << std::get<std::string>(row[0]);
  }
}

}  // namespace
}  // namespace fl::analysis
