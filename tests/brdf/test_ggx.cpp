// GGX kernels (brdf/ggx.h): normalization, the Smith Λ form, sampling points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "brdf/ggx.h"
#include "quadrature.h"

namespace fl::brdf {
namespace {

using test::gauss_legendre;
using test::GaussRule;
using test::integrate_theta;

constexpr double kPi = std::numbers::pi;
// The quadrature of a smooth normalized density.
constexpr double kNormalizationTolerance = 1e-6;

TEST(GgxKernels, NdfProjectedAreaIsOne) {
  static const GaussRule g = gauss_legendre(16);
  for (double alpha : {1e-3, 0.05, 0.3, 0.7, 1.0}) {
    const double s = integrate_theta(
        [&](double t) { return 2 * kPi * ggx_ndf(std::cos(t), alpha) * std::cos(t) * std::sin(t); }, kPi / 2,
        alpha, {}, g);
    EXPECT_NEAR(s, 1.0, kNormalizationTolerance) << alpha;
  }
}

// Heitz 2014, eq. 72 and 99: Λ(θ) = (−1 + √(1 + α² tan²θ))/2, G₁ = 1/(1 + Λ(v)) and the
// height-correlated G₂ = 1/(1 + Λ(v) + Λ(l)) = 4 (n·v)(n·l) V.
TEST(GgxKernels, VisibilityMatchesTheSmithLambdaForm) {
  auto lambda = [](double c, double alpha) {
    const double tan2 = (1 - c * c) / (c * c);
    return 0.5 * (-1 + std::sqrt(1 + alpha * alpha * tan2));
  };
  for (double alpha : {0.01, 0.2, 0.6, 1.0})
    for (double nov : {0.05, 0.4, 0.9, 1.0})
      for (double nol : {0.1, 0.5, 0.99}) {
        const double g2 = 1 / (1 + lambda(nov, alpha) + lambda(nol, alpha));
        EXPECT_NEAR(4 * nov * nol * smith_ggx_correlated_visibility(nov, nol, alpha), g2, 1e-12);
        EXPECT_NEAR(smith_ggx_g1(nov, alpha), 1 / (1 + lambda(nov, alpha)), 1e-12);
      }
}

TEST(GgxKernels, HammersleyPointsAreStratified) {
  constexpr int n = 16;
  std::vector<double> u1;
  for (int i = 0; i < n; ++i) {
    const auto p = hammersley(i, n);
    EXPECT_DOUBLE_EQ(p.u2, (i + 0.5) / n);
    u1.push_back(p.u1);
  }
  std::sort(u1.begin(), u1.end());
  for (int i = 0; i < n; ++i) EXPECT_DOUBLE_EQ(u1[i], static_cast<double>(i) / n);
}

TEST(GgxKernels, VisibleNormalSamplesLieInTheViewHemisphere) {
  const Vec3 v = view_from_nov(0.3);
  for (int i = 0; i < 256; ++i) {
    const auto p = hammersley(i, 256);
    const auto h = sample_ggx_vndf(v, 0.5, p.u1, p.u2);
    EXPECT_NEAR(dot(h, h), 1.0, 1e-12);
    EXPECT_GE(dot(v, h), 0.0);
    EXPECT_GE(h.z, 0.0);
  }
}

}  // namespace
}  // namespace fl::brdf
