// GGX kernels (brdf/ggx.h): normalization, the Smith Λ form, sampling points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "brdf/ggx.h"
#include "ggx_reference.h"
#include "quadrature.h"

namespace fl::brdf {
namespace {

using test::gauss_legendre;
using test::GaussRule;
using test::integrate_theta;

constexpr double kPi = std::numbers::pi;
// The quadrature of a smooth normalized density.
constexpr double kNormalizationTolerance = 1e-6;
// Two algebraic forms of the same closed formula, relative. Filament's (n·h)²(α² − 1) + 1 cancels
// as n·h → 1, to a relative rounding of about ε/α² (2e-10 at α = 1e-3).
constexpr double kNdfFormsTolerance = 1e-9;
// Means over 16384 Hammersley points against the quadrature of the density they sample (measured
// ≤ 3.1e-5; the quadrature alone integrates D_v to 1 within 2.5e-6, at the kink where v·h = 0).
constexpr double kSampleMeanTolerance = 1e-4;

TEST(GgxKernels, NdfProjectedAreaIsOne) {
  static const GaussRule g = gauss_legendre(16);
  for (double alpha : {1e-3, 0.05, 0.3, 0.7, 1.0}) {
    const double s = integrate_theta(
        [&](double t) { return 2 * kPi * ggx_ndf(std::cos(t), alpha) * std::cos(t) * std::sin(t); },
        kPi / 2, alpha, {}, g);
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

TEST(GgxKernels, NdfMatchesWaltersTangentForm) {
  for (double alpha : {1e-3, 0.05, 0.3, 0.7, 1.0})
    for (double noh : {1.0, 0.99, 0.9, 0.6, 0.2, 0.01}) {
      const double want = test::ggx_ref::ndf(noh, alpha);
      EXPECT_NEAR(ggx_ndf(noh, alpha), want, kNdfFormsTolerance * want) << alpha << " " << noh;
    }
}

// Heitz 2018, eq. 1: h drawn by sample_ggx_vndf has the density D_v(h) = G₁(v) max(0, v·h)
// D(h)/(n·v). The means of h's components over the samples must be the integrals of h·D_v by
// quadrature (with D and G₁ = 1/(1 + Λ) from ggx_reference.h); ∫ D_v = 1 is the normalization.
TEST(GgxKernels, VisibleNormalSamplesFollowTheVisibleNormalDensity) {
  constexpr int kSamples = 16384;
  for (double alpha : {0.1, 0.5, 1.0})
    for (double nov : {1.0, 0.8, 0.3}) {
      const Vec3 v = view_from_nov(nov);
      const double g1 = 1 / (1 + test::ggx_ref::lambda(nov, alpha));
      auto moment = [&](int k) {
        return test::integrate_sphere(
            [&](double x, double y, double z) {
              const double voh = v.x * x + v.y * y + v.z * z;
              const double dv = g1 * std::max(0.0, voh) * test::ggx_ref::ndf(z, alpha) / nov;
              return dv * (k == 0 ? 1.0 : (k == 1 ? x : z));
            },
            kPi / 2, alpha);
      };
      double mx = 0, mz = 0;
      for (int i = 0; i < kSamples; ++i) {
        const auto p = hammersley(i, kSamples);
        const Vec3 h = sample_ggx_vndf(v, alpha, p.u1, p.u2);
        mx += h.x / kSamples;
        mz += h.z / kSamples;
      }
      EXPECT_NEAR(moment(0), 1.0, kSampleMeanTolerance) << alpha << " " << nov;
      EXPECT_NEAR(mx, moment(1), kSampleMeanTolerance) << alpha << " " << nov;
      EXPECT_NEAR(mz, moment(2), kSampleMeanTolerance) << alpha << " " << nov;
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

// The view's factors computed once (GgxVndfWeight, the renderer's and the tables' inner loops) give
// every per-sample kernel's value to the bit: the same operations in the same order.
TEST(GgxKernels, AViewsFactorsGiveThePerSampleKernelsBitForBit) {
  for (const double nov : {1e-4, 0.05, 0.3, 0.7, 1.0})
    for (const double alpha : {0.002, 0.04, 0.25, 0.64, 1.0}) {
      const GgxVndfWeight view(nov, alpha);
      const Vec3 v = view_from_nov(nov);
      for (int k = 0; k < 64; ++k) {
        const auto u = hammersley(static_cast<std::uint32_t>(k), 64u);
        const Vec3 h = sample_ggx_vndf(v, alpha, u.u1, u.u2);
        const Vec3 l = reflect(v, h);
        EXPECT_EQ(view(l.z), ggx_vndf_weight(nov, l.z, alpha));
        EXPECT_EQ(view.reflection_pdf(h.z), ggx_vndf_reflection_pdf(nov, h.z, alpha));
        // A direction of its own (not the mirror of h), as the lights draw them, above or below.
        const Vec3 d = normalize(Vec3{u.u1 - 0.5, u.u2 - 0.5, 0.4 - u.u1});
        const Vec3 hd = normalize(Vec3{v.x + d.x, v.y + d.y, v.z + d.z});
        EXPECT_EQ(view.lobe_cos(d.z, hd.z), ggx_lobe_cos(v, d, alpha));
      }
    }
}

}  // namespace
}  // namespace fl::brdf
