// GGX lookup tables (analysis/lut.h): the DFG and LTC-moment integrals against an independent
// deterministic quadrature, the fitted LTC table against the lobes it fits.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "analysis/lut.h"
#include "brdf/ggx.h"
#include "fit/ltc_fit.h"
#include "quadrature.h"

namespace fl::analysis {
namespace {

using test::gauss_legendre;
using test::GaussRule;
using test::integrate_panel;
using test::integrate_theta;
using test::Values;
using test::operator+;
using test::operator*;

constexpr double kPi = std::numbers::pi;
// The tables against the quadrature (the test tolerance).
constexpr double kQuadratureTolerance = 1e-3;
// Identities that hold sample by sample (same samples, different accumulation): only rounding.
constexpr double kSameSamplesTolerance = 1e-12;
// n_D at normal incidence for the smallest roughness tested.
constexpr double kSmoothNormTolerance = 1e-3;
// A fitted LTC integrates to one.
constexpr double kLtcUnitIntegralTolerance = 1e-3;
// A fitted LTC lobe: relative L2 error against the GGX lobe it fits, by quadrature. Near normal
// incidence (n·v ≥ 0.9) the LTC is close; towards grazing the three-parameter LTC cannot follow
// the GGX lobe (the worst cells of a 64×64 table, n·v < 0.05, reach ~0.5).
constexpr double kMaxLobeRelativeL2NearNormal = 0.1;
constexpr double kMaxLobeRelativeL2 = 0.35;
// The fit error the table reports (sample estimate) against the same error by quadrature.
constexpr double kFitErrorEstimateTolerance = 0.02;
// The horizon-clipped sphere form factor against a quadrature over the cap.
constexpr double kFormFactorTolerance = 1e-4;

LutOptions options(int samples, int threads = 0) {
  LutOptions o;
  o.samples = samples;
  o.threads = threads;
  return o;
}

struct Reference {
  double n_d = 0, f_d = 0, l_d = 0, dfg1 = 0, dfg2 = 0;
};

// ∫ g(v·h) D V (n·l) dl over l with n·l > 0, written over half vectors h = (θ, φ):
// dl = 4 (v·h) dω_h, and n·l > 0 ⇔ cos φ > c(θ) = −(cos θ_v / sin θ_v) cot 2θ, which is −1 at
// θ₁ = (π/2 − θ_v)/2 and +1 at θ₂ = (π/2 + θ_v)/2. The φ-range is integrated exactly.
Reference reference_moments(double nov, double alpha) {
  static const GaussRule g_theta = gauss_legendre(16), g_phi = gauss_legendre(32);
  const double theta_v = std::acos(nov), sin_v = std::sin(theta_v);
  const double theta1 = 0.5 * (kPi / 2 - theta_v), theta2 = 0.5 * (kPi / 2 + theta_v);
  auto f_theta = [&](double theta) -> Values {
      const double ct = std::cos(theta), st = std::sin(theta);
      double phi_max = kPi;
      if (sin_v > 0) {
        const double c = -(nov / sin_v) * std::cos(2 * theta) / std::sin(2 * theta);
        phi_max = c <= -1 ? kPi : (c >= 1 ? 0 : std::acos(c));
      } else if (theta >= kPi / 4) {
        phi_max = 0;
      }
      if (phi_max <= 0) return Values{};
      const double d = brdf::ggx_ndf(ct, alpha);
      auto f_phi = [&](double phi) -> Values {
        const double voh = sin_v * st * std::cos(phi) + nov * ct;
        const double nol = 2 * voh * ct - nov;
        if (nol <= 0 || voh <= 0) return Values{};
        const double w = d * brdf::smith_ggx_correlated_visibility(nov, nol, alpha) * nol * 4 * voh;
        const double m = 1 - voh, m5 = m * m * m * m * m;
        return {w, w * m5, w * voh * m5 * m, w * (1 - m5)};
      };
      return (2 * st) * integrate_panel<Values>(f_phi, 0, phi_max, g_phi);
  };
  const Values v = integrate_theta<Values>(f_theta, theta2, alpha, {theta1}, g_theta);
  return {v[0], v[1], v[2], v[3], v[1]};
}

TEST(Lut, NormTendsToOneAtNormalIncidenceAsRoughnessVanishes) {
  double previous = 0;
  for (double roughness : {0.8, 0.5, 0.2, 0.05, 0.01}) {
    const double n_d = integrate_moments(1.0, roughness * roughness).n_d;
    EXPECT_GT(n_d, previous) << roughness;
    previous = n_d;
  }
  EXPECT_NEAR(previous, 1.0, kSmoothNormTolerance);
}

TEST(Lut, DfgChannelsAreTheNormAndFresnelMomentCellByCell) {
  const auto grid = dfg_grid(8);
  const auto dfg = dfg_table(grid, options(2048));
  const auto mom = moments_table(grid, options(2048));
  for (size_t k = 0; k < dfg.cells.size(); ++k) {
    EXPECT_NEAR(mom.cells[k].n_d, dfg.cells[k].dfg1 + dfg.cells[k].dfg2, kSameSamplesTolerance) << k;
    EXPECT_NEAR(mom.cells[k].f_d, dfg.cells[k].dfg2, kSameSamplesTolerance) << k;
  }
}

TEST(Lut, ResultsDoNotDependOnThreads) {
  const auto grid = ltc_grid(6);
  const auto a = moments_table(grid, options(512, 1));
  const auto b = moments_table(grid, options(512, 3));
  for (size_t k = 0; k < a.cells.size(); ++k) {
    EXPECT_EQ(a.cells[k].n_d, b.cells[k].n_d);
    EXPECT_EQ(a.cells[k].l_d, b.cells[k].l_d);
  }
}

// Max |table − quadrature| over every cell of both grids; also run at 64×64 by hand with
// --gtest_also_run_disabled_tests (FullTables).
struct MaxDiff {
  double dfg1 = 0, dfg2 = 0, n_d = 0, f_d = 0, l_d = 0;
};
MaxDiff compare_with_quadrature(int size, int samples) {
  MaxDiff m;
  const auto dfg = dfg_table(dfg_grid(size), options(samples));
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const auto ref = reference_moments(dfg.grid.nov[i], dfg.grid.alpha[j]);
      const auto& c = dfg.cells[dfg.grid.index(i, j)];
      m.dfg1 = std::max(m.dfg1, std::abs(c.dfg1 - ref.dfg1));
      m.dfg2 = std::max(m.dfg2, std::abs(c.dfg2 - ref.dfg2));
    }
  const auto mom = moments_table(ltc_grid(size), options(samples));
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const auto ref = reference_moments(mom.grid.nov[i], mom.grid.alpha[j]);
      const auto& c = mom.cells[mom.grid.index(i, j)];
      m.n_d = std::max(m.n_d, std::abs(c.n_d - ref.n_d));
      m.f_d = std::max(m.f_d, std::abs(c.f_d - ref.f_d));
      m.l_d = std::max(m.l_d, std::abs(c.l_d - ref.l_d));
    }
  return m;
}

TEST(Lut, TablesAgreeWithQuadrature) {
  const auto m = compare_with_quadrature(10, kLutSamples);
  EXPECT_LT(m.dfg1, kQuadratureTolerance);
  EXPECT_LT(m.dfg2, kQuadratureTolerance);
  EXPECT_LT(m.n_d, kQuadratureTolerance);
  EXPECT_LT(m.f_d, kQuadratureTolerance);
  EXPECT_LT(m.l_d, kQuadratureTolerance);
}

TEST(Lut, DISABLED_FullTablesAgreeWithQuadrature) {
  const auto m = compare_with_quadrature(64, kLutSamples);
  std::printf("max |table - quadrature| at 64x64: dfg1 %.3g, dfg2 %.3g, n_d %.3g, f_d %.3g, l_d %.3g\n", m.dfg1,
              m.dfg2, m.n_d, m.f_d, m.l_d);
  EXPECT_LT(std::max({m.dfg1, m.dfg2, m.n_d, m.f_d, m.l_d}), 2e-3);
}

// ---- LTC fits

// ∫ f over the sphere in the LTC frame's polar coordinates (θ from Z), panels in θ.
double integrate_sphere(const std::function<double(const brdf::Vec3&)>& f, double theta_end) {
  return test::integrate_sphere([&](double x, double y, double z) { return f({x, y, z}); }, theta_end);
}

TEST(Ltc, FittedLobesIntegrateToOneAndMatchTheBrdf) {
  constexpr int size = 8;
  const auto t = fit_ltc_table(size, options(2048));
  int checked = 0;
  for (int j = size / 2; j < size; ++j)
    for (int i = 0; i < size; i += 2) {
      const int k = t.grid.index(i, j);
      const auto& c = t.cells[k];
      const auto& mo = t.moments[k];
      EXPECT_TRUE(c.fit.usable) << i << "," << j;
      const auto frame = i == 0 ? fit::LtcFrame{} : fit::ltc_frame_from_average_direction(mo.average_dir);
      // The normalized LTC: polar coordinates about the frame's Z (it vanishes for z < 0 there).
      const double unit = integrate_sphere(
          [&](const brdf::Vec3& w) { return fit::ltc_density(c.params.m11, c.params.m22, c.params.m13, w.x, w.y, w.z); },
          kPi / 2);
      EXPECT_NEAR(unit, 1.0, kLtcUnitIntegralTolerance) << i << "," << j;

      // Relative L2 error of n_D·D_LTC against ρ cos over the whole sphere (world coordinates).
      const brdf::Vec3 v = brdf::view_from_nov(t.grid.nov[i]);
      const double alpha = t.grid.alpha[j];
      auto ltc_world = [&](const brdf::Vec3& w) {
        const brdf::Vec3 f{brdf::dot(w, frame.x), brdf::dot(w, frame.y), brdf::dot(w, frame.z)};
        return mo.n_d * fit::ltc_density(c.params.m11, c.params.m22, c.params.m13, f.x, f.y, f.z);
      };
      const double err2 = integrate_sphere(
          [&](const brdf::Vec3& w) {
            const double d = brdf::ggx_lobe_cos(v, w, alpha) - ltc_world(w);
            return d * d;
          },
          kPi);
      const double norm2 = integrate_sphere(
          [&](const brdf::Vec3& w) {
            const double b = brdf::ggx_lobe_cos(v, w, alpha);
            return b * b;
          },
          kPi / 2);
      const double rel = std::sqrt(err2 / norm2);
      EXPECT_LT(rel, t.grid.nov[i] >= 0.9 ? kMaxLobeRelativeL2NearNormal : kMaxLobeRelativeL2) << i << "," << j;
      EXPECT_NEAR(c.fit_error, rel, kFitErrorEstimateTolerance) << i << "," << j;
      ++checked;
    }
  EXPECT_EQ(checked, 16);
}

TEST(Ltc, TextureEntriesAreTheNormalizedInverse) {
  const auto t = fit_ltc_table(4, options(512));
  for (const auto& c : t.cells) {
    // M · M⁻¹ = I.
    for (int r = 0; r < 3; ++r)
      for (int q = 0; q < 3; ++q) {
        double s = 0;
        for (int k = 0; k < 3; ++k) s += c.m(r, k) * c.m_inv(k, q);
        EXPECT_NEAR(s, r == q ? 1.0 : 0.0, 1e-9);
      }
    EXPECT_DOUBLE_EQ(c.inv_packed[0], c.m_inv(0, 0) / c.m_inv(1, 1));
    EXPECT_DOUBLE_EQ(c.inv_packed[1], c.m_inv(2, 0) / c.m_inv(1, 1));
    EXPECT_DOUBLE_EQ(c.inv_packed[2], c.m_inv(0, 2) / c.m_inv(1, 1));
    EXPECT_DOUBLE_EQ(c.inv_packed[3], c.m_inv(2, 2) / c.m_inv(1, 1));
  }
}

// Cosine-weighted solid angle of a spherical cap (centre at angle ω from the normal, radius σ)
// above the horizon, over π sin²σ, by quadrature over the cap.
double reference_form_factor(double z, double len) {
  static const GaussRule g = gauss_legendre(48);
  const double sigma = std::asin(std::sqrt(len)), omega = std::acos(z);
  double s = 0;
  for (int pr = 0; pr < 8; ++pr)
    s += integrate_panel(
        [&](double rho) {
          double inner = 0;
          for (int pp = 0; pp < 16; ++pp)
            inner += integrate_panel(
                [&](double psi) {
                  return std::max(0.0, std::cos(omega) * std::cos(rho) + std::sin(omega) * std::sin(rho) * std::cos(psi));
                },
                pp * kPi / 8, (pp + 1) * kPi / 8, g);
          return inner * std::sin(rho);
        },
        pr * sigma / 8, (pr + 1) * sigma / 8, g);
  return s / (kPi * len);
}

TEST(Ltc, SphereFormFactorMatchesCapQuadrature) {
  for (double len : {0.05, 0.3, 0.7, 0.95})
    for (double z : {-0.9, -0.3, 0.0, 0.2, 0.6, 1.0})
      EXPECT_NEAR(horizon_clipped_sphere_form_factor(z, len), reference_form_factor(z, len), kFormFactorTolerance)
          << z << "," << len;
  EXPECT_DOUBLE_EQ(horizon_clipped_sphere_form_factor(0.5, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(horizon_clipped_sphere_form_factor(-0.5, 0.0), 0.0);
}

}  // namespace
}  // namespace fl::analysis
