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
