// The fit to colours a caller computes (fit::fit_model_colours): it finds the parameters that made
// the target's colours, and, although Ceres asks for a point several times with bounds (the step's
// cost, the projected line search's trial with its gradient, the accepted point's Jacobian), the
// caller's colours are computed at most twice at any one point: once for the residuals, once as
// the centre of the central differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "fit/fit.h"
#include "fresnel/models/cook_torrance.h"
#include "fresnel/registered_models.h"

namespace fl {
namespace {

// The colours a target's `colours` gives at 7 angles from `colour_at(cos θ, params, channel)`, the
// truth its own colours at `truth_params`, in a CIELAB of white (1, 1, 1).
template <class ColourAt>
fit::ColourTarget own_colours_target(const std::vector<double>& truth_params, ColourAt colour_at) {
  static const std::vector<double> mu{1.0, 0.8, 0.6, 0.4, 0.2, 0.1, 0.05};
  fit::ColourTarget target;
  target.to_lab = {color::Mat3{}, color::Xyz{1.0, 1.0, 1.0}};
  target.colours = [colour_at](const double* p, color::Rgb* out) {
    for (size_t i = 0; i < mu.size(); ++i)
      for (int c = 0; c < 3; ++c) out[i][c] = colour_at(mu[i], p, c);
    return true;
  };
  std::vector<color::Rgb> truth(mu.size());
  target.colours(truth_params.data(), truth.data());
  for (const auto& t : truth) target.truth_lab.push_back(target.to_lab(t));
  return target;
}

// The target's colours, each call's parameters recorded in `calls`.
void record_calls(fit::ColourTarget& target, size_t params,
                  std::vector<std::vector<double>>& calls) {
  target.colours = [inner = target.colours, params, &calls](const double* p, color::Rgb* out) {
    calls.emplace_back(p, p + params);
    return inner(p, out);
  };
}

TEST(ColourFit, FindsTheParametersAndComputesEachPointAtMostTwice) {
  const fresnel::Model schlick = fresnel::model_from_name("schlick").model;
  const std::vector<double> f0{0.9, 0.6, 0.3};
  auto target = own_colours_target(f0, [](double mu, const double* p, int c) {
    return p[c] + (1.0 - p[c]) * std::pow(1.0 - mu, 5.0);
  });
  std::vector<std::vector<double>> calls;
  record_calls(target, 3, calls);
  fit::FitOptions options;
  options.max_solves = 1;
  // Not a grey start: at a = b = 0 CIEDE2000's hue has no derivative to follow.
  const auto r = fit::fit_model_colours(schlick, target, {{0.7, 0.5, 0.4}}, options);
  ASSERT_TRUE(r.usable) << r.termination;
  EXPECT_GT(r.iterations, 2);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.parameters[c], f0[c], 1e-6);
  std::map<std::vector<double>, int> at_point;
  int most = 0;
  for (const auto& point : calls) most = std::max(most, ++at_point[point]);
  EXPECT_LE(most, 2);
}

// Cook–Torrance: F0 per channel (parameters 0, 1, 2), the representative η and κ shared (3, 4).
TEST(ColourFit, StepsTheChannelsTogetherAndTheSharedParametersAlone) {
  const fresnel::Model model = fresnel::model_from_name("cook_torrance").model;
  const std::vector<double> truth_params{0.95, 0.64, 0.54, 0.2, 3.0};
  auto target = own_colours_target(truth_params, [](double mu, const double* p, int c) {
    return fresnel::cook_torrance(mu, p[c], p[3], p[4]);
  });
  std::vector<std::vector<double>> calls;
  record_calls(target, 5, calls);
  fit::FitOptions options;
  options.max_solves = 1;
  const auto r = fit::fit_model_colours(model, target, {{0.9, 0.7, 0.5, 0.25, 2.8}}, options);
  ASSERT_TRUE(r.usable) << r.termination;
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(r.parameters[k], truth_params[k], 1e-5) << k;
  // A call within a difference step (2e-6 of a parameter, at least 2e-6) of the centre (the last
  // call that was not) that moves some of its parameters but not all is a central difference: it
  // moves the three F0s or one shared parameter.
  const std::vector<std::vector<int>> groups{{0, 1, 2}, {3}, {4}};
  int channel_steps = 0;
  size_t centre = 0;
  for (size_t n = 1; n < calls.size(); ++n) {
    std::vector<int> moved;
    bool near = true;
    for (int k = 0; k < 5; ++k) {
      const double d = std::abs(calls[n][k] - calls[centre][k]);
      if (d > 0) moved.push_back(k);
      near = near && d <= 2.5e-6 * std::max(1.0, std::abs(calls[n][k]));
    }
    if (!near || moved.size() == 5) {
      centre = n;
      continue;
    }
    if (moved.empty()) continue;
    EXPECT_NE(std::find(groups.begin(), groups.end(), moved), groups.end()) << moved.size();
    channel_steps += moved.size() == 3;
  }
  EXPECT_GT(channel_steps, 0);
}

}  // namespace
}  // namespace fl
