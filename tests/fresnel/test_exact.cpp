// Fresnel identities for the exact equations.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "fresnel/exact.h"

namespace fl::fresnel {
namespace {

constexpr double kIdentityTolerance = 1e-12;

// pbrt-v4 FrComplex: an independent implementation in complex arithmetic.
double fr_complex_reference(double cos_i, std::complex<double> eta) {
  using C = std::complex<double>;
  const double sin2_i = 1 - cos_i * cos_i;
  const C sin2_t = sin2_i / (eta * eta);
  const C cos_t = std::sqrt(1.0 - sin2_t);
  const C r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const C r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return (std::norm(r_parl) + std::norm(r_perp)) / 2;
}

TEST(Exact, NormalIncidenceDielectric) {
  for (double n : {1.0001, 1.33, 1.5, 2.417, 4.0, 0.5}) {
    const double r0 = ((n - 1) / (n + 1)) * ((n - 1) / (n + 1));
    EXPECT_NEAR(fresnel_dielectric(1.0, n), r0, kIdentityTolerance) << n;
    EXPECT_NEAR(fresnel_conductor(1.0, std::complex<double>(n, 0)), r0, kIdentityTolerance) << n;
  }
}

TEST(Exact, NormalIncidenceConductor) {
  for (auto eta : {std::complex<double>(0.2, 3.5), {1.5, 1.0}, {2.8, 3.1}, {0.05, 80}}) {
    const double n = eta.real(), k = eta.imag();
    const double r0 = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    EXPECT_NEAR(fresnel_conductor(1.0, eta), r0, kIdentityTolerance);
  }
}

TEST(Exact, ConductorWithZeroKappaEqualsDielectric) {
  for (double n : {0.6, 0.9, 1.2, 1.5, 2.4, 5.0})
    for (int i = 0; i <= 900; ++i) {
      const double c = std::cos(i * 0.1 * M_PI / 180.0);
      EXPECT_NEAR(fresnel_conductor(c, std::complex<double>(n, 0)), fresnel_dielectric(c, n), kIdentityTolerance)
          << "n=" << n << " theta=" << i * 0.1;
    }
}

TEST(Exact, ConductorMatchesComplexArithmetic) {
  for (auto eta : {std::complex<double>(0.15, 3.6), {0.47, 2.4}, {2.9, 3.0}, {1.5, 0.001}, {0.01, 80}})
    for (int i = 0; i < 90; ++i) {
      const double c = std::cos(i * M_PI / 180.0);
      EXPECT_NEAR(fresnel_conductor(c, eta), fr_complex_reference(c, eta), 1e-10) << eta << " " << i;
    }
}

TEST(Exact, GrazingIncidenceReflectsEverything) {
  for (auto eta : {std::complex<double>(1.5, 0), {0.2, 3.5}, {2.8, 3.1}, {0.01, 80}, {0.7, 0}})
    EXPECT_NEAR(fresnel_conductor(0.0, eta), 1.0, kIdentityTolerance) << eta;
  EXPECT_NEAR(fresnel_dielectric(0.0, 1.5), 1.0, kIdentityTolerance);
}

TEST(Exact, BrewsterAngleExtinguishesP) {
  for (double n : {1.33, 1.5, 2.417}) {
    const double theta_b = std::atan(n);
    const auto p = fresnel_conductor_polarized(std::cos(theta_b), n, 0.0);
    EXPECT_NEAR(p.r_p, 0.0, kIdentityTolerance) << n;
    EXPECT_GT(p.r_s, 0.01);
    EXPECT_NEAR(fresnel_dielectric_polarized(std::cos(theta_b), n).r_p, 0.0, kIdentityTolerance);
  }
}

TEST(Exact, TotalInternalReflection) {
  const double eta = 1.0 / 1.5;  // seen from inside glass
  const double cos_critical = std::sqrt(1 - eta * eta);
  EXPECT_NEAR(fresnel_dielectric(cos_critical - 1e-9, eta), 1.0, kIdentityTolerance);
  EXPECT_NEAR(fresnel_conductor(cos_critical - 1e-9, std::complex<double>(eta, 0)), 1.0, 1e-9);
  EXPECT_LT(fresnel_dielectric(cos_critical + 0.01, eta), 1.0);
}

}  // namespace
}  // namespace fl::fresnel
