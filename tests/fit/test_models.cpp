// Fresnel model kernels, Gulbrandsen's mapping and Ceres fits. The generic checks over every
// model (Jacobians, batch, domains, derivation) are in tests/fresnel/test_registry.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/presets/preset_tables.h"
#include "analysis/study/study.h"
#include "analysis/tables/tables.h"
#include "fit/fit.h"
#include "fresnel/derive.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"

namespace fl {
namespace {

using fresnel::Model;
constexpr double kExact = 1e-12;

TEST(Models, SchlickEndpoints) {
  for (double f0 : {0.0, 0.04, 0.5, 0.95, 1.0}) {
    EXPECT_NEAR(fresnel::schlick(1.0, f0), f0, kExact);
    EXPECT_NEAR(fresnel::schlick(0.0, f0), 1.0, kExact);
    EXPECT_NEAR(fresnel::generalized_schlick(1.0, f0, 0.8, 3.0), f0, kExact);
    EXPECT_NEAR(fresnel::generalized_schlick(0.0, f0, 0.8, 3.0), 0.8, kExact);
  }
}

TEST(Models, F82ModelPassesThroughF82) {
  for (double f0 : {0.02, 0.5, 0.9, 0.97})
    for (double f82 : {0.3, 0.6, 0.85, 0.99}) {
      EXPECT_NEAR(fresnel::hoffman_f82_unclamped(fresnel::kCosTheta82, f0, f82), f82, kExact);
      EXPECT_NEAR(fresnel::hoffman_f82(1.0, f0, f82), f0, kExact);
      EXPECT_NEAR(fresnel::hoffman_f82(0.0, f0, f82), 1.0, kExact);
    }
}

TEST(Models, F82ModelIsLazanyiWithAlphaSix) {
  const double f0 = 0.8, f82 = 0.7, a = fresnel::f82_coefficient(f0, f82);
  for (double c : {0.05, 0.3, 0.7})
    EXPECT_NEAR(fresnel::lazanyi(c, f0, a, 6.0), fresnel::hoffman_f82_unclamped(c, f0, f82),
                kExact);
}

TEST(Models, GulbrandsenRoundTrips) {
  for (double r : {0.01, 0.2, 0.5, 0.9, 0.99})
    for (double g : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const double eta = fresnel::gulbrandsen_eta(r, g);
      EXPECT_NEAR(fresnel::gulbrandsen_g(r, eta), g, kExact) << r << " " << g;
      // κ is chosen so that the conductor's normal-incidence reflectance is r.
      const double kappa = fresnel::gulbrandsen_kappa(r, eta);
      EXPECT_NEAR(fresnel::fresnel_conductor<double>(1.0, eta, kappa), r, 1e-12) << r << " " << g;
      EXPECT_NEAR(fresnel::gulbrandsen(1.0, r, g), r, 1e-12);
      EXPECT_NEAR(fresnel::gulbrandsen(0.0, r, g), 1.0, 1e-12);
    }
}

TEST(Models, CookTorranceInterpolatesFromF0ToOne) {
  for (double f0 : {0.1, 0.9}) {
    EXPECT_NEAR(fresnel::cook_torrance(1.0, f0, 1.5, 3.0), f0, kExact);
    EXPECT_NEAR(fresnel::cook_torrance(0.0, f0, 1.5, 3.0), 1.0, kExact);
  }
}

// A target from a real material (gold) in ACEScg.
struct GoldTarget {
  analysis::Context ctx{[] {
    analysis::Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  analysis::LoadedMaterial gold =
      analysis::load_material(ctx, spectral::resolve_material("gold", ctx.settings().paths));
  std::vector<color::Rgb> truth = analysis::ground_truth_curve(ctx, gold.ior, 1.0);
  fit::CurveTarget target = analysis::curve_target(ctx, truth);
  fresnel::DerivedParameters derived = fresnel::derive_parameters(
      ctx.rgb_weights(), ctx.space().rgb_to_xyz, gold.ior, 1.0, fresnel::kDefaultPointSampleNm);
  fresnel::DeriveInput input() const {
    return {derived, gold.ior, 1.0, ctx.rgb_weights(), ctx.cos_thetas(), truth};
  }
};

// Synthetic curves made by each model with known parameters are fitted back from a perturbed start.
constexpr double kRecoveredRms = 1e-4;  // ΔE2000: the fit must reproduce the curve
constexpr double kRecoveredParam = 2e-3;

TEST(Fit, RecoversKnownParametersFromSyntheticCurves) {
  GoldTarget g;
  for (const auto& spec : fresnel::model_specs()) {
    // Known parameters: the fitted ones for gold, so they are plausible and identifiable.
    const auto truth_params =
        fit::fit_model(spec.model, g.target, {fresnel::derived_model_params(spec.model, g.input())})
            .parameters;
    const auto synthetic = fresnel::evaluate_curve(spec.model, truth_params, g.ctx.cos_thetas());
    const auto target = analysis::curve_target(g.ctx, synthetic);
    auto start = truth_params;
    for (size_t i = 0; i < start.size(); ++i) start[i] *= (i % 2 ? 0.95 : 1.04);
    const auto r = fit::fit_model(spec.model, target, {start});
    EXPECT_TRUE(r.usable) << spec.name;
    EXPECT_LT(fit::rms_from_cost(r.cost, target.cos_thetas.size()), kRecoveredRms) << spec.name;
    if (spec.identifiable) {  // the unit's declaration (UnitFeatures::identifiable)
      for (size_t i = 0; i < start.size(); ++i)
        EXPECT_NEAR(r.parameters[i], truth_params[i], kRecoveredParam)
            << spec.name << " parameter " << i;
    }
  }
}

TEST(Fit, NoUsableStartStillReturnsParameters) {
  GoldTarget g;
  fit::CurveTarget broken = g.target;
  for (auto& lab : broken.truth_lab) lab.L = std::nan("");  // every residual is NaN
  const auto r = fit::fit_model(
      fresnel::model_of<fresnel::models::F82>, broken,
      {fresnel::derived_model_params(fresnel::model_of<fresnel::models::F82>, g.input())});
  EXPECT_FALSE(r.usable);
  EXPECT_EQ(r.parameters.size(), 6u);
  EXPECT_EQ(r.termination, "NO_USABLE_SOLUTION");
}

// The methods table and the F82 model's gain over Schlick, measured on the catalog.
TEST(Acceptance, MethodsTableAndF82Median) {
  analysis::Settings s;
  s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
  const analysis::Context ctx(s);
  const auto ms = analysis::load_catalog(ctx);
  const auto studies = analysis::study_materials(ctx, ms, {});
  const auto methods = analysis::methods_table(ctx, studies);
  const auto schlick = analysis::schlick_table(ctx, ms);
  ASSERT_EQ(methods.rows.size(), 14u);
  std::vector<double> schlick_rms, f82_rms;
  std::printf("%-10s %8s %10s %10s\n", "metal", "schlick", "refl_refl", "fitted");
  for (size_t i = 0; i < methods.rows.size(); ++i) {
    const auto& row = methods.rows[i];
    const double refl_refl = std::get<double>(row[5]), fitted = std::get<double>(row[6]);
    std::printf("%-10s %8.3f %10.3f %10.3f\n", std::get<std::string>(row[0]).c_str(),
                std::get<double>(row[1]), refl_refl, fitted);
    EXPECT_LE(refl_refl, 0.10) << std::get<std::string>(row[0]);
    EXPECT_LE(fitted, refl_refl) << std::get<std::string>(row[0]);
    for (const auto& srow : schlick.rows)
      if (srow[0] == row[0]) {
        EXPECT_EQ(std::get<double>(row[1]), std::get<double>(srow[3]))
            << "Schlick column = table schlick";
      }
  }
  for (const auto& st : studies)
    if (st.material->material.material_class == spectral::MaterialClass::Metal) {
      schlick_rms.push_back(
          st.result(fresnel::model_of<fresnel::models::Schlick>).derived_error.rms);
      f82_rms.push_back(st.result(fresnel::model_of<fresnel::models::F82>).fitted_error.rms);
    }
  std::sort(schlick_rms.begin(), schlick_rms.end());
  std::sort(f82_rms.begin(), f82_rms.end());
  const double med_s = 0.5 * (schlick_rms[6] + schlick_rms[7]),
               med_f = 0.5 * (f82_rms[6] + f82_rms[7]);
  std::printf("median RMS over metals: Schlick %.3f, fitted F82 %.3f (%.1fx lower)\n", med_s, med_f,
              med_s / med_f);
  EXPECT_GE(med_s / med_f, 3.0);

  // Each model's fit depends on its own starts only: the presets' study, which fits RGB η, κ alone,
  // publishes the same presets as the study that fits every model.
  const auto presets = analysis::study_materials(ctx, ms, analysis::presets_study_options(false));
  const auto eta_kappa = fresnel::model_of<fresnel::models::FresnelRgb>;
  for (size_t i = 0; i < presets.size(); ++i)
    for (const auto& r : presets[i].models) {
      EXPECT_EQ(r.fitted.parameters.empty(), r.model != eta_kappa)
          << fresnel::model_spec(r.model).name;
      EXPECT_EQ(r.derived, studies[i].result(r.model).derived);
    }
  const auto full = analysis::presets_table(ctx, studies).rows,
             alone = analysis::presets_table(ctx, presets).rows;
  ASSERT_EQ(full.size(), alone.size());
  const auto same = [](const Cell& a, const Cell& b) {
    const auto* x = std::get_if<double>(&a);
    const auto* y = std::get_if<double>(&b);
    return x && y ? (*x == *y || (std::isnan(*x) && std::isnan(*y)))
                  : a == b;  // coverage_k is NaN without k data
  };
  for (size_t i = 0; i < full.size(); ++i)
    for (size_t j = 0; j < full[i].size(); ++j)
      EXPECT_TRUE(same(full[i][j], alone[i][j])) << i << ", " << j;
}

}  // namespace
}  // namespace fl
