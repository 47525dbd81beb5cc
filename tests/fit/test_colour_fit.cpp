// The fit to colours a caller computes (fit::fit_model_colours): it finds the parameters that made
// the target's colours, and, although Ceres asks for a point several times with bounds (the step's
// cost, the projected line search's trial with its gradient, the accepted point's Jacobian), the
// caller's colours are computed at most twice at any one point: once for the residuals, once as
// the centre of the central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "fit/fit.h"
#include "fresnel/registered_models.h"

namespace fl {
namespace {

TEST(ColourFit, FindsTheParametersAndComputesEachPointAtMostTwice) {
  const fresnel::Model schlick = fresnel::model_from_name("schlick").model;
  const std::vector<double> f0{0.9, 0.6, 0.3};
  const std::vector<double> mu{1.0, 0.8, 0.6, 0.4, 0.2, 0.1, 0.05};
  std::map<std::vector<double>, int> calls;
  fit::ColourTarget target;
  target.to_lab = {color::Mat3{}, color::Xyz{1.0, 1.0, 1.0}};
  target.colours = [&](const double* p, color::Rgb* out) {
    ++calls[std::vector<double>(p, p + 3)];
    for (size_t i = 0; i < mu.size(); ++i)
      for (int c = 0; c < 3; ++c) out[i][c] = p[c] + (1.0 - p[c]) * std::pow(1.0 - mu[i], 5.0);
    return true;
  };
  std::vector<color::Rgb> truth(mu.size());
  target.colours(f0.data(), truth.data());
  for (const auto& t : truth) target.truth_lab.push_back(target.to_lab(t));
  calls.clear();
  fit::FitOptions options;
  options.max_solves = 1;
  // Not a grey start: at a = b = 0 CIEDE2000's hue has no derivative to follow.
  const auto r = fit::fit_model_colours(schlick, target, {{0.7, 0.5, 0.4}}, options);
  ASSERT_TRUE(r.usable) << r.termination;
  EXPECT_GT(r.iterations, 2);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.parameters[c], f0[c], 1e-6);
  int most = 0;
  for (const auto& [point, n] : calls) most = std::max(most, n);
  EXPECT_LE(most, 2);
}

}  // namespace
}  // namespace fl
