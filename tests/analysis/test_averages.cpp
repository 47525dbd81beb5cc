// The hemispherical averages of the ground truth and of the models (analysis/tables/averages.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/tables/averages.h"
#include "fresnel/registry.h"

namespace fl::analysis {
namespace {

// Gauss–Legendre on 8 panels of 20 nodes against a closed form: rounding only.
constexpr double kQuadrature = 1e-12;
// The table prints model averages computed by the units' closed forms or by quadrature; both agree
// with an analytic average to rounding.
constexpr double kClosedForm = 1e-12;

// The hemispherical (diffuse) reflectance 2∫₀¹ R(μ) μ dμ of a lossless dielectric of index n seen
// from air, in closed form (Walton 1978; the form in Molenaar, ten Bosch & Zijp 1999, eq. A2).
double dielectric_hemispherical_reflectance(double n) {
  const double n2 = n * n, n4 = n2 * n2;
  return 0.5 + (n - 1) * (3 * n + 1) / (6 * (n + 1) * (n + 1)) +
         n2 * (n2 - 1) * (n2 - 1) / std::pow(n2 + 1, 3) * std::log((n - 1) / (n + 1)) -
         2 * n * n2 * (n2 + 2 * n - 1) / ((n2 + 1) * (n4 - 1)) +
         8 * n4 * (n4 + 1) / ((n2 + 1) * (n4 - 1) * (n4 - 1)) * std::log(n);
}

Context test_context() {
  Settings s;
  s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
  return Context(s);
}

TEST(Averages, DielectricTruthMatchesWaltonsClosedForm) {
  const Context ctx = test_context();
  for (const double n : {1.33, 1.5, 2.4}) {
    spectral::ComplexIorSpectrum ior{ctx.grid(), {}};
    ior.ior.assign(ctx.grid().count, {n, 0.0});
    const color::Rgb avg = ground_truth_average(ctx, ior);
    // A flat reflectance r has RGB r·Σ_λ w(λ) per channel.
    for (int c = 0; c < 3; ++c) {
      double white = 0;
      for (const auto& w : ctx.rgb_weights()) white += w[c];
      EXPECT_NEAR(avg[c], dielectric_hemispherical_reflectance(n) * white, kQuadrature)
          << "n = " << n << ", channel " << c;
    }
  }
}

TEST(Averages, PerfectConductorAveragesToWhite) {
  const Context ctx = test_context();
  spectral::ComplexIorSpectrum ior{ctx.grid(), {}};
  ior.ior.assign(ctx.grid().count, {0.0, 1e9});  // |R| = 1 at every angle
  const color::Rgb avg = ground_truth_average(ctx, ior);
  for (int c = 0; c < 3; ++c) {
    double white = 0;
    for (const auto& w : ctx.rgb_weights()) white += w[c];
    EXPECT_NEAR(avg[c], white, 1e-8) << c;  // R = 1 − O(1/κ)
  }
}

TEST(Averages, TableRowsAgreeWithSchlicksClosedForm) {
  const Context ctx = test_context();
  const auto materials = load_catalog(ctx);
  StudyOptions o;
  o.fit = false;
  const auto studies = study_materials(ctx, materials, o);
  const Table t = averages_table(ctx, studies);
  ASSERT_EQ(t.rows.size(), studies.size() * size_t{fresnel::Registry::kSize});
  const int model = column_index(t, "model"), kind = column_index(t, "parameters");
  const int r = column_index(t, "f_avg_r");
  size_t checked = 0;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const auto& row = t.rows[i];
    if (std::get<std::string>(row[model]) != "schlick" ||
        std::get<std::string>(row[kind]) != "derived")
      continue;
    // Schlick: 2∫(F0 + (1 − F0)(1 − μ)⁵) μ dμ = F0 + (1 − F0)/21.
    const auto& st = studies[i / fresnel::Registry::kSize];
    const auto& f0 = st.result(fresnel::model_of<fresnel::models::Schlick>).derived;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(std::get<double>(row[r + c]), f0[c] + (1 - f0[c]) / 21.0, kClosedForm);
    ++checked;
  }
  EXPECT_EQ(checked, studies.size());
}

}  // namespace
}  // namespace fl::analysis
