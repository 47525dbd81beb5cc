// Hemispherical averages F_avg = 2∫F(μ)μ dμ (fresnel/average.h) against an independent
// Gauss–Legendre quadrature of each kernel (tests/quadrature.h): the units' closed forms (Schlick,
// F82, generalized Schlick, Lazányi) and the library's own quadrature for the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fresnel/average.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "quadrature.h"

namespace fl {
namespace {

// The acceptance bound for closed forms against quadrature.
constexpr double kClosedFormTolerance = 1e-6;
// Two quadratures of the same kernel: ~1e-12 for the smooth ones; Cook–Torrance's max(0, ·) puts a
// kink inside [0, 1] where either rule converges slowly (measured 3e-7).
constexpr double kQuadratureTolerance = 1e-6;

// 2∫F μ dμ with t = μ on [0, 1] through integrate_panel's cosine substitution (which also
// removes the (1 − μ)^p endpoint behaviour), 64 nodes on each of 8 panels.
color::Rgb reference_average(fresnel::Model m, const std::vector<double>& p) {
  static const test::GaussRule g = test::gauss_legendre(64);
  color::Rgb sum{};
  for (int k = 0; k < 8; ++k) {
    const auto v = test::integrate_panel<test::Values>(
        [&](double mu) {
          const auto f = fresnel::evaluate_curve(m, p, {mu})[0];
          return test::Values{2 * mu * f.r, 2 * mu * f.g, 2 * mu * f.b, 0};
        },
        k / 8.0, (k + 1) / 8.0, g);
    sum = sum + color::Rgb{v[0], v[1], v[2]};
  }
  return sum;
}

std::vector<std::vector<double>> probe_params(const fresnel::ModelSpec& spec) {
  std::vector<double> mid;
  for (const auto& r : spec.bounds()) mid.push_back(0.5 * (r.lo + r.hi));
  return {fresnel::example_params(spec.model), mid};
}

TEST(Average, ClosedFormsAndQuadratureAgreeWithAnIndependentQuadrature) {
  int closed = 0;
  double worst_closed = 0;
  for (const auto& spec : fresnel::model_specs()) {
    for (const auto& p : probe_params(spec)) {
      const auto ref = reference_average(spec.model, p);
      const auto quad = fresnel::hemispherical_average_quadrature(spec.model, p);
      const auto avg = fresnel::hemispherical_average(spec.model, p);
      const bool in_closed_form = fresnel::average_in_closed_form(spec.model, p);
      closed += in_closed_form;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(quad[c], ref[c], kQuadratureTolerance) << spec.name;
        EXPECT_NEAR(avg[c], ref[c], in_closed_form ? kClosedFormTolerance : kQuadratureTolerance)
            << spec.name;
        if (!in_closed_form) continue;
        EXPECT_NEAR(spec.closed_form_average(p.data(), c), ref[c], kClosedFormTolerance)
            << spec.name;
        worst_closed =
            std::max(worst_closed, std::abs(spec.closed_form_average(p.data(), c) - ref[c]));
      }
    }
  }
  std::printf("max |closed form - quadrature| over %d closed-form cases: %.3g\n", closed,
              worst_closed);
  EXPECT_GE(closed, 6);  // Schlick, F82, generalized Schlick, Lazányi on (nearly) every probe
}

// Analytic values: Schlick's F_avg = F0 + (1 − F0)/21, so white F0 = 1 averages to 1 and F0 = 0
// to 1/21; the exact equations of an index-matched interface reflect nothing.
TEST(Average, AnalyticValues) {
  const auto s =
      fresnel::hemispherical_average(fresnel::model_of<fresnel::models::Schlick>, {1.0, 0.0, 0.5});
  EXPECT_NEAR(s.r, 1.0, 1e-15);
  EXPECT_NEAR(s.g, 1.0 / 21.0, 1e-15);
  EXPECT_NEAR(s.b, 0.5 + 0.5 / 21.0, 1e-15);
  const auto rgb = fresnel::hemispherical_average(fresnel::model_of<fresnel::models::FresnelRgb>,
                                                  {1, 0, 1, 0, 1, 0});
  EXPECT_NEAR(rgb.r, 0.0, 1e-15);
}

}  // namespace
}  // namespace fl
