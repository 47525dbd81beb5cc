// The exact Fresnel equations against analytic values, an independent complex-arithmetic
// implementation and the identities of the interface (energy, Stokes, reciprocity, Snell).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "fresnel/exact.h"
#include "fresnel/ground_truth.h"

namespace fl::fresnel {
namespace {

constexpr double kIdentityTolerance = 1e-12;
// The same reflectance evaluated from both sides: the back side's cos θ is itself computed
// (√(1 − sin²)), which near grazing amplifies rounding.
constexpr double kReciprocityTolerance = 1e-9;

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
      EXPECT_NEAR(fresnel_conductor(c, std::complex<double>(n, 0)), fresnel_dielectric(c, n),
                  kIdentityTolerance)
          << "n=" << n << " theta=" << i * 0.1;
    }
}

TEST(Exact, ConductorMatchesComplexArithmetic) {
  for (auto eta :
       {std::complex<double>(0.15, 3.6), {0.47, 2.4}, {2.9, 3.0}, {1.5, 0.001}, {0.01, 80}})
    for (int i = 0; i < 90; ++i) {
      const double c = std::cos(i * M_PI / 180.0);
      EXPECT_NEAR(fresnel_conductor(c, eta), fr_complex_reference(c, eta), 1e-10)
          << eta << " " << i;
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

// ---- Identities of the dielectric interface, with the transmission side written independently
// (Born & Wolf §1.5.2): Snell's law n_i sin θ_i = n_t sin θ_t, and the amplitude coefficients for
// relative index η = n_t/n_i,
//   r_s = (cos θ_i − η cos θ_t)/(cos θ_i + η cos θ_t),  t_s = 2 cos θ_i/(cos θ_i + η cos θ_t),
//   r_p = (η cos θ_i − cos θ_t)/(η cos θ_i + cos θ_t),  t_p = 2 cos θ_i/(η cos θ_i + cos θ_t),
// with transmittance T = η (cos θ_t / cos θ_i) |t|² (the flux through the interface).

struct Side {
  double cos_t = 0, t_s = 0, t_p = 0, r_s = 0, r_p = 0;  // amplitudes
  bool tir = false;
};
Side refract(double cos_i, double eta) {
  Side o;
  const double sin_t = std::sqrt(1 - cos_i * cos_i) / eta;  // Snell
  if (sin_t >= 1) {
    o.tir = true;
    return o;
  }
  o.cos_t = std::sqrt(1 - sin_t * sin_t);
  o.r_s = (cos_i - eta * o.cos_t) / (cos_i + eta * o.cos_t);
  o.r_p = (eta * cos_i - o.cos_t) / (eta * cos_i + o.cos_t);
  o.t_s = 2 * cos_i / (cos_i + eta * o.cos_t);
  o.t_p = 2 * cos_i / (eta * cos_i + o.cos_t);
  return o;
}

const double kEtas[] = {1.0001, 1.33, 1.5, 2.417, 4.0, 1 / 1.33, 1 / 1.5, 1 / 2.417};

TEST(Exact, EnergyConservationReflectedPlusTransmittedIsOne) {
  for (double eta : kEtas)
    for (int i = 0; i < 900; ++i) {
      const double c = std::cos(i * 0.1 * M_PI / 180.0);
      const auto p = fresnel_dielectric_polarized(c, eta);
      const Side o = refract(c, eta);
      if (o.tir) {
        EXPECT_EQ(p.r_s, 1.0) << eta << " " << i;
        EXPECT_EQ(p.r_p, 1.0) << eta << " " << i;
        continue;
      }
      const double t_s = eta * o.cos_t / c * o.t_s * o.t_s, t_p = eta * o.cos_t / c * o.t_p * o.t_p;
      EXPECT_NEAR(p.r_s + t_s, 1.0, kIdentityTolerance) << eta << " " << i;
      EXPECT_NEAR(p.r_p + t_p, 1.0, kIdentityTolerance) << eta << " " << i;
    }
}

// Stokes relations: seen from the other side at the refracted angle, r' = −r and t t' = 1 − r²;
// so the reflectance is the same from both sides (reciprocity), and Snell's law holds in the code.
TEST(Exact, StokesRelationsAndReciprocity) {
  for (double eta : kEtas)
    for (int i = 0; i < 900; ++i) {
      const double c = std::cos(i * 0.1 * M_PI / 180.0);
      const Side a = refract(c, eta);
      if (a.tir) continue;
      const Side b = refract(a.cos_t, 1 / eta);
      ASSERT_FALSE(b.tir);
      EXPECT_NEAR(b.cos_t, c, 1e-9) << eta << " " << i;
      EXPECT_NEAR(b.r_s, -a.r_s, kReciprocityTolerance) << eta << " " << i;
      EXPECT_NEAR(b.r_p, -a.r_p, kReciprocityTolerance) << eta << " " << i;
      EXPECT_NEAR(a.t_s * b.t_s, 1 - a.r_s * a.r_s, kReciprocityTolerance) << eta << " " << i;
      EXPECT_NEAR(a.t_p * b.t_p, 1 - a.r_p * a.r_p, kReciprocityTolerance) << eta << " " << i;
      EXPECT_NEAR(cos_transmitted(c, eta), a.cos_t, kIdentityTolerance) << eta << " " << i;
      const auto front = fresnel_dielectric_polarized(c, eta),
                 back = fresnel_dielectric_polarized(a.cos_t, 1 / eta);
      EXPECT_NEAR(front.r_s, back.r_s, kReciprocityTolerance) << eta << " " << i;
      EXPECT_NEAR(front.r_p, back.r_p, kReciprocityTolerance) << eta << " " << i;
      EXPECT_NEAR(fresnel_conductor(c, eta, 0.0), fresnel_conductor(a.cos_t, 1 / eta, 0.0),
                  kReciprocityTolerance)
          << eta << " " << i;
    }
}

// Ground truth sums R(λ)·w(λ) over wavelengths; its column pass (vectorized) must give bit for bit
// the scalar kernel's sum, in the same order, over every branch of the kernel: conductors,
// lossless indices above and below 1 (total internal reflection), an index-matched wavelength,
// normal and grazing incidence, and a 1 nm grid longer than one column pass.
TEST(GroundTruth, ColumnPassEqualsTheScalarKernelBitForBit) {
  for (double step_nm : {5.0, 1.0}) {
    spectral::ComplexIorSpectrum ior;
    ior.grid = spectral::SpectralGrid::visible(step_nm);
    std::vector<color::Rgb> w;
    for (int i = 0; i < ior.grid.count; ++i) {
      const double t = double(i) / ior.grid.count;
      const std::complex<double> kinds[] = {
          {0.2 + t, 3.0 - t}, {1.5 + 0.1 * t, 0.0}, {0.7, 0.0}, {1.0, 0.0}, {2.4, 1e-210}};
      ior.ior.push_back(kinds[i % 5]);
      w.push_back({0.01 * (1 + i % 7), 0.02 * t, 0.003 * (i % 3)});
    }
    for (double eta_outside : {1.0, 1.33})
      for (double cos_theta : {1.0, 0.7, 0.2, 1e-3, 0.0}) {
        color::Rgb scalar;
        for (size_t i = 0; i < w.size(); ++i)
          scalar = scalar + fresnel_conductor(cos_theta, ior.ior[i] / eta_outside) * w[i];
        const color::Rgb column = spectral_reflectance_rgb(w, ior, cos_theta, eta_outside);
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(column[c], scalar[c]) << step_nm << " nm, cos " << cos_theta;
      }
  }
}

}  // namespace
}  // namespace fl::fresnel
