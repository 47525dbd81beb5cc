// The blend, gamut, external-medium and internal-reflection tables
// (analysis/tables/media_tables.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/tables/media_tables.h"
#include "analysis/tables/tables.h"
#include "fresnel/media.h"
#include "util/errors.h"

namespace fl::analysis {
namespace {

// Linear models commute with linear operations up to rounding.
constexpr double kLinearModelDe = 1e-9;
constexpr double kExact = 1e-12;
// Two evaluations of the same reflectance spectrum in RGB (only rounding in the weighted sums).
constexpr double kExactSpectrum = 1e-12;

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
  std::printf("worst Gulbrandsen blend: %s + %s = %.3f\n",
              std::get<std::string>(g.rows[0][0]).c_str(),
              std::get<std::string>(g.rows[0][1]).c_str(), worst);
  // The talk: the worst pairs land around 1.5-2.5 ΔE2000.
  EXPECT_GE(worst, 1.5);
  EXPECT_LE(worst, 2.5);
  for (size_t i = 1; i < g.rows.size(); ++i)
    EXPECT_GE(std::get<double>(g.rows[i - 1][2]), std::get<double>(g.rows[i][2]))
        << "largest first";
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
  for (const auto& row : t.rows)
    EXPECT_LE(std::get<double>(row[column(t, "schlick")]), kLinearModelDe);
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

// Born & Wolf §1.5.2, written here from Snell's law and the amplitude coefficients, for light in a
// medium of index n_i meeting a material of complex index n_t (k ≥ 0): cos θ_t = √(1 − sin²θ_t)
// with sin θ_t = (n_i/n_t) sin θ_i (complex for an absorbing material or past the critical angle),
// r_s = (n_i cos θ_i − n_t cos θ_t)/(n_i cos θ_i + n_t cos θ_t), r_p = (n_t cos θ_i − n_i cos
// θ_t)/(n_t cos θ_i + n_i cos θ_t).
double reflectance_in_medium(std::complex<double> n_t, double n_i, double cos_i) {
  using C = std::complex<double>;
  const double sin_i = std::sqrt(std::max(0.0, 1 - cos_i * cos_i));
  const C sin_t = n_i * sin_i / n_t;
  C cos_t = std::sqrt(1.0 - sin_t * sin_t);
  if (cos_t.imag() < 0)
    cos_t = -cos_t;  // the decaying branch, for absorption and past the critical angle
  const C r_s = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t);
  const C r_p = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t);
  return 0.5 * (std::norm(r_s) + std::norm(r_p));
}

const LoadedMaterial& catalog_material(const std::string& key) {
  for (const auto& m : catalog().materials)
    if (m.material.key == key) return m;
  throw std::runtime_error("no catalog material " + key);
}

// The ground truth in an external medium, through the general path (the index relative to the
// medium is never 1 here): a constant-index dielectric reflects the same fraction at every
// wavelength, so its RGB is that fraction times the pipeline's RGB of a perfect reflector; a
// metal's spectrum is computed wavelength by wavelength and pushed through the same pipeline.
TEST(Media, GroundTruthInAMediumMatchesSnellAndFresnel) {
  const auto& c = catalog();
  const auto& tourmaline = catalog_material("tourmaline");
  ASSERT_EQ(tourmaline.ior.ior.front(), std::complex<double>(1.64, 0.0));
  const color::Rgb white = c.ctx.spectrum_to_rgb(std::vector<double>(c.ctx.grid().count, 1.0));
  // Media below, just below, just above and above the material's index (TIR past asin(1.64/1.7)).
  for (double medium : {1.0, 1.333, 1.64 * (1 - 1e-3), 1.64 * (1 + 1e-3), 1.7}) {
    for (double cos_i : c.ctx.cos_thetas()) {
      const double r = reflectance_in_medium(1.64, medium, cos_i);
      const color::Rgb got = ground_truth_rgb(c.ctx, tourmaline.ior, cos_i, medium);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(got[ch], r * white[ch], kExactSpectrum) << medium << " " << cos_i;
    }
  }
  const auto& gold = catalog_material("gold");
  for (double medium : {1.0, 1.333, 1.5}) {
    for (double cos_i : c.ctx.cos_thetas()) {
      std::vector<double> spectrum;
      for (const auto& n : gold.ior.ior)
        spectrum.push_back(reflectance_in_medium(n, medium, cos_i));
      const color::Rgb want = c.ctx.spectrum_to_rgb(spectrum);
      const color::Rgb got = ground_truth_rgb(c.ctx, gold.ior, cos_i, medium);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(got[ch], want[ch], kExactSpectrum) << medium << " " << cos_i;
    }
  }
}

TEST(Media, AirRowsMatchTheSchlickTable) {
  const auto& c = catalog();
  const Table t = media_table(c.ctx, c.studies);
  const Table s = schlick_table(c.ctx, c.materials);
  const size_t medium = column(t, "medium"), sym = column(t, "symmetric");
  int air = 0;
  for (const auto& row : t.rows) {
    if (std::get<std::string>(row[medium]) != "air") continue;
    ++air;
    for (const auto& srow : s.rows) {
      if (srow[0] == row[0]) {
        EXPECT_NEAR(std::get<double>(row[sym]), std::get<double>(srow[3]), kExact);
      }
    }
  }
  EXPECT_EQ(air, 28);
}

TEST(Internal, NormalIncidenceAndCriticalAngle) {
  const auto& c = catalog();
  for (const auto& st : c.studies) {
    if (st.material->material.material_class == spectral::MaterialClass::Metal) continue;
    spectral::ComplexIorSpectrum inverse = st.material->ior;
    for (auto& v : inverse.ior) v = {1.0 / v.real(), 0.0};
    const color::Rgb exact = ground_truth_rgb(c.ctx, inverse, 1.0, 1.0);
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(exact[ch], fresnel::schlick_internal(1.0, st.derived.f0[ch]), kExact)
          << st.material->material.name;
  }
  const Table t = internal_table(c.ctx, c.studies);
  ASSERT_EQ(t.rows.size(), 14u);
  for (const auto& row : t.rows) {
    EXPECT_NEAR(std::get<double>(row[column(t, "de00_normal")]), 0.0, 1e-9);
    EXPECT_NEAR(std::get<double>(row[column(t, "exact_at_critical")]), 1.0, kExact)
        << std::get<std::string>(row[0]);
    EXPECT_NEAR(std::get<double>(row[column(t, "schlick_at_critical")]), 1.0, kExact)
        << std::get<std::string>(row[0]);
  }
}

}  // namespace
}  // namespace fl::analysis
