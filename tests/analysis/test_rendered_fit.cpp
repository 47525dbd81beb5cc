// Parameters fitted to the rendered result (analysis/lut/rendered_fit.h, lut_accuracy.h).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/gold_shading.h"
#include "analysis/lut/lut_accuracy.h"
#include "analysis/lut/rendered_fit.h"
#include "analysis/pipeline/materials.h"
#include "fresnel/registry.h"
#include "util/errors.h"

namespace fl::analysis {
namespace {

using fresnel::model_of;

// A step of 1e-3 in a reflectance parameter moves the rendered RMS ΔE2000 by ~1e-2 at most; a
// minimum's neighbours lie above it by second-order amounts, so they may tie it to rounding only.
constexpr double kStep = 1e-3;
constexpr double kRounding = 1e-12;

// The combined rendered RMS over both lightings, computed here from rendered_de00 (the errors the
// table prints) rather than from the fit's residuals.
double combined_rms(const Context& ctx, const std::vector<color::Rgb>& truth, fresnel::Model m,
                    const std::vector<double>& p, const std::vector<ShadingPoint>& points) {
  double sum = 0;
  size_t n = 0;
  for (const Lighting l : kRenderedFitLightings)
    for (double d : rendered_de00(ctx, truth, m, p, l, points)) {
      sum += d * d;
      ++n;
    }
  return std::sqrt(sum / static_cast<double>(n));
}

using Gold = test::GoldShading;

// The F82 fit to the render is a minimum of what the table reports: no better than the derived and
// curve-fitted sets it starts from, and every parameter moved by ±kStep raises the error.
TEST(RenderedFit, F82OnGoldIsALocalMinimumOfTheRenderedError) {
  const Gold g;
  const auto f82 = model_of<fresnel::models::F82>;
  const auto& r = g.study.result(f82);
  const auto fit = fit_rendered(g.ctx, g.truth, f82, g.points, {r.derived, r.fitted.parameters},
                                g.study.lossless);
  ASSERT_TRUE(fit.usable);
  const double best = combined_rms(g.ctx, g.truth, f82, fit.parameters, g.points);
  EXPECT_LT(best, combined_rms(g.ctx, g.truth, f82, r.derived, g.points));
  EXPECT_LT(best, combined_rms(g.ctx, g.truth, f82, r.fitted.parameters, g.points));
  for (size_t i = 0; i < fit.parameters.size(); ++i)
    for (const double step : {-kStep, kStep}) {
      auto moved = fit.parameters;
      moved[i] += step;
      EXPECT_GE(combined_rms(g.ctx, g.truth, f82, moved, g.points), best - kRounding)
          << "parameter " << i << " moved by " << step;
    }
}

// The table's rendered rows are those fits: for a model evaluated at n·v (Gulbrandsen) the
// rendered set trades its curve for the render, far better rendered and far worse on the curve.
TEST(RenderedFit, TableRowsTradeTheCurveForTheRender) {
  const Gold g;
  const auto cs = rendered_candidates(g.ctx, g.study, g.points);
  const RenderedCandidate *fitted = nullptr, *rendered = nullptr;
  for (const auto& c : cs)
    if (c.model == model_of<fresnel::models::Gulbrandsen>) {
      if (c.set == ParameterSet::Fitted) fitted = &c;
      if (c.set == ParameterSet::Rendered) rendered = &c;
    }
  ASSERT_TRUE(fitted && rendered);
  EXPECT_LT(rendered->ibl.rms, 0.6 * fitted->ibl.rms);
  EXPECT_LT(rendered->area.rms, 0.6 * fitted->area.rms);
  EXPECT_GT(rendered->punctual_rms, 10 * fitted->punctual_rms);
}

// Zinc's generalized Schlick is a rendered fit with a long flat valley: stopped early, its
// parameters land anywhere along it and the table's figures move with the truth's last digits.
// fit_rendered must end where an independent solve from the derived set alone, run to 20 times
// the iterations and to the rounding of the cost (then restarted from its own end), ends: the
// figures the table prints (3 decimals) within a fifth of their last digit.
TEST(RenderedFit, ZincGeneralizedSchlickReachesTheOptimum) {
  const Context ctx{[] {
    Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  const auto set = load_materials(ctx, {"zinc"}, {});
  const auto study = study_materials(ctx, set.materials, {}).front();
  const auto points = lut_accuracy_points();
  const auto truth = lobe_truth(ctx, set.materials.front(), points);
  const auto m = model_of<fresnel::models::GeneralizedSchlick>;
  const auto& r = study.result(m);
  const auto fit =
      fit_rendered(ctx, truth, m, points, {r.derived, r.fitted.parameters}, study.lossless);
  ASSERT_TRUE(fit.usable);
  EXPECT_FALSE(fit.iteration_limit) << fit.iterations;

  fit::ColourTarget target;
  target.to_lab = {ctx.space().rgb_to_xyz, ctx.space().white};
  for (size_t l = 0; l < kRenderedFitLightings.size(); ++l)
    for (const auto& t : truth) target.truth_lab.push_back(target.to_lab(t));
  target.colours = [&](const double* p, color::Rgb* out) {
    const std::vector<double> params(p, p + r.derived.size());
    for (const Lighting l : kRenderedFitLightings) {
      engine_shading(m, params, l, points, out + (l == Lighting::Ibl ? 0 : points.size()));
    }
    return true;
  };
  fit::FitOptions longer;
  longer.max_solves = 1;
  longer.max_iterations = 20 * kRenderedFitMaxIterations;
  longer.function_tolerance = 1e-15;
  auto reference = fit::fit_model_colours(m, target, {r.derived}, longer);
  reference = fit::fit_model_colours(m, target, {reference.parameters}, longer);
  ASSERT_TRUE(reference.usable);

  constexpr double kPrinted = 2e-4;  // a fifth of the table's last digit
  EXPECT_NEAR(combined_rms(ctx, truth, m, fit.parameters, points),
              combined_rms(ctx, truth, m, reference.parameters, points), kPrinted);
  const auto target_curve = curve_target(ctx, study.truth);
  const auto curve_rms = [&](const std::vector<double>& p) {
    return curve_error(ctx, target_curve.truth_lab, fresnel::evaluate_curve(m, p, ctx.cos_thetas()))
        .rms;
  };
  EXPECT_NEAR(curve_rms(fit.parameters), curve_rms(reference.parameters), kPrinted);
  for (const Lighting l : kRenderedFitLightings) {
    const auto a = error_stats(rendered_de00(ctx, truth, m, fit.parameters, l, points));
    const auto b = error_stats(rendered_de00(ctx, truth, m, reference.parameters, l, points));
    EXPECT_NEAR(a.max, b.max, kPrinted) << lighting_name(l);
  }
}

TEST(RenderedFit, ParameterSetNames) {
  EXPECT_EQ(parameter_set_from_name("rendered"), ParameterSet::Rendered);
  EXPECT_EQ(parameter_set_from_name("Fitted"), ParameterSet::Fitted);
  try {
    parameter_set_from_name("renderd");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'rendered'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl::analysis
