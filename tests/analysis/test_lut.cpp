// GGX lookup tables (analysis/lut/lut.h) against independent references: the DFG and moment
// integrals against a Gauss–Legendre quadrature of the GGX lobe written from the papers
// (ggx_reference.h), the mirror limit, energy bounds, and ltc_code's published 64 × 64 fit (its n_D
// and, on one error metric, its lobes); the ltc_1 texture read back the way a shader reads it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/ltc/ltc_fit.h"
#include "analysis/ltc/ltc_reference.h"
#include "analysis/lut/lut.h"
#include "brdf/ggx.h"
#include "dfg_reference.h"
#include "ggx_reference.h"
#include "quadrature.h"

namespace fl::analysis {
namespace {

namespace ref = test::ggx_ref;
using fresnel::Term;
using test::gauss_legendre;
using test::GaussRule;
using test::integrate_panel;
using test::integrate_theta;
using test::reference_moments;
using test::Values;
using test::operator+;
using test::operator*;

constexpr double kPi = std::numbers::pi;
// The tables (8192 quasi-Monte Carlo points per cell) against the quadrature: measured ≤ 1.8e-4
// over a 10 × 10 grid, 2.5e-4 over 64 × 64.
constexpr double kQuadratureTolerance = 3e-4;
// The mirror limit at α = 1e-4: Λ ∝ α² tan²θ, and the lobe's spread shifts the mean v·h by
// O(α² log 1/α) (GGX slopes have heavy tails): ~1e-6 for n·v ≥ 0.15.
constexpr double kMirrorTolerance = 1e-5;
// A fitted LTC integrates to one, by quadrature over its support, a hemisphere (measured 2e-15).
constexpr double kLtcUnitIntegralTolerance = 1e-9;
// A fitted LTC lobe against the GGX lobe, relative L2 error by quadrature, over ltc_code's
// published fit of the same cell. The error itself is large towards grazing (0.29 for ltc_code's
// fit at n·v = 0.27, α = 0.33, 0.19 for ours): an LTC cannot follow the GGX lobe there; what can be
// asked of a fit is to do as well as the reference. Neither fit minimizes this error; where both
// are near the same optimum (normal incidence, α = 1) ours is up to 1.2 % above (measured ratio
// ≤ 1.012).
constexpr double kLobeAgainstLtcCodeRatio = 1.02;
// ltc_code's n_D (float, stratified samples) against the quadrature: per cell and on average.
constexpr double kLtcCodeNormTolerance = 1.5e-2;
constexpr double kLtcCodeNormMeanTolerance = 2e-3;
// The ltc_1 texture's lobe against the fit's density: the same function, only rounding.
constexpr double kTextureDensityTolerance = 1e-9;
// The held-out error the table reports (256 + 256 fresh directions) against the same error by
// quadrature, relative (measured ≤ 6 %).
constexpr double kFitErrorEstimateTolerance = 0.1;
// The horizon-clipped sphere form factor against a quadrature over the cap.
constexpr double kFormFactorTolerance = 1e-4;

LutOptions options(int samples, int threads = 0) {
  LutOptions o;
  o.samples = samples;
  o.threads = threads;
  return o;
}

TEST(Lut, NormTendsToOneAtNormalIncidenceAsRoughnessVanishes) {
  double previous = 0;
  for (double roughness : {0.8, 0.5, 0.2, 0.05, 0.01}) {
    const double n_d = integrate_moments(1.0, roughness * roughness)[Term::One];
    EXPECT_GT(n_d, previous) << roughness;
    previous = n_d;
  }
  EXPECT_NEAR(previous, 1.0, kMirrorTolerance);  // roughness 0.01: α = 1e-4
}

// A mirror (α → 0): D concentrates on h = n, so v·h → n·v and G₂ → 1 (Λ ∝ α² tan²θ). The lobe
// integrates to 1, the Fresnel moment to (1 − n·v)⁵ and the F82 moment to n·v (1 − n·v)⁶.
TEST(Lut, MirrorLimit) {
  constexpr double kAlpha = 1e-4;
  for (double nov : {1.0, 0.9, 0.7, 0.5, 0.3, 0.15}) {
    const double m = 1 - nov, m5 = std::pow(m, 5);
    const auto dfg = integrate_dfg(nov, kAlpha);
    const auto mo = integrate_moments(nov, kAlpha);
    EXPECT_NEAR(dfg[Term::One], 1 - m5, kMirrorTolerance) << nov;
    EXPECT_NEAR(dfg[Term::Schlick], m5, kMirrorTolerance) << nov;
    EXPECT_NEAR(dfg[Term::F82], nov * m5 * m, kMirrorTolerance) << nov;
    EXPECT_NEAR(mo[Term::One], 1.0, kMirrorTolerance) << nov;
    EXPECT_NEAR(mo[Term::Schlick], m5, kMirrorTolerance) << nov;
    EXPECT_NEAR(mo[Term::F82], nov * m5 * m, kMirrorTolerance) << nov;
    // The lobe's mean direction is the mirror direction (sin θ_v, 0, cos θ_v) reflected: (−x, z).
    EXPECT_NEAR(mo.average_dir.x, -std::sqrt(1 - nov * nov), kMirrorTolerance) << nov;
    EXPECT_NEAR(mo.average_dir.z, nov, kMirrorTolerance) << nov;
  }
}

// Energy: a single-scattering lobe without Fresnel reflects at most what arrives (n_D ≤ 1), each
// weight (1 − v·h)⁵ ≤ 1 and (v·h)(1 − v·h)⁶ ≤ (1 − v·h)⁵ keeps 0 ≤ l_D ≤ f_D ≤ n_D, and the DFG
// channels split n_D into two non-negative parts.
TEST(Lut, EnergyBoundsInEveryCell) {
  constexpr int kSize = 8;
  const auto dfg = dfg_table(dfg_grid(kSize), options(2048));
  for (const auto& c : dfg.cells) {
    EXPECT_GE(c[Term::One], 0.0);
    EXPECT_GE(c[Term::Schlick], 0.0);
    EXPECT_LE(c[Term::One] + c[Term::Schlick], 1.0);
  }
  const auto mom = moments_table(ltc_grid(kSize), options(2048));
  for (int i = 0; i < kSize; ++i)
    for (int j = 0; j < kSize; ++j) {
      const auto& c = mom.cells[mom.grid.index(i, j)];
      EXPECT_GE(c[Term::F82], 0.0) << i << "," << j;
      EXPECT_LE(c[Term::F82], c[Term::Schlick]) << i << "," << j;
      EXPECT_LE(c[Term::Schlick], c[Term::One]) << i << "," << j;
      EXPECT_LE(c[Term::One], 1.0) << i << "," << j;
    }
}

TEST(Lut, ResultsDoNotDependOnThreads) {
  const auto grid = ltc_grid(6);
  const auto a = moments_table(grid, options(512, 1));
  const auto b = moments_table(grid, options(512, 3));
  for (size_t k = 0; k < a.cells.size(); ++k) {
    EXPECT_EQ(a.cells[k][Term::One], b.cells[k][Term::One]);
    EXPECT_EQ(a.cells[k][Term::F82], b.cells[k][Term::F82]);
  }
}

// Max |table − quadrature| over every cell of both grids; also run at 64×64 by hand with
// --gtest_also_run_disabled_tests (FullTables).
struct MaxDiff {
  double dfg1 = 0, dfg2 = 0, dfg_f82 = 0, n_d = 0, f_d = 0, l_d = 0;
};
// The DFG table only, at every cell of a size × size grid.
MaxDiff compare_dfg_with_quadrature(int size, int samples) {
  MaxDiff m;
  const auto dfg = dfg_table(dfg_grid(size), options(samples));
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const auto ref = reference_moments(dfg.grid.nov[i], dfg.grid.alpha[j]);
      const auto& c = dfg.cells[dfg.grid.index(i, j)];
      m.dfg1 = std::max(m.dfg1, std::abs(c[Term::One] - ref.dfg1));
      m.dfg2 = std::max(m.dfg2, std::abs(c[Term::Schlick] - ref.dfg2));
      m.dfg_f82 = std::max(m.dfg_f82, std::abs(c[Term::F82] - ref.l_d));  // the F82 term's integral
    }
  return m;
}
MaxDiff compare_with_quadrature(int size, int samples) {
  MaxDiff m = compare_dfg_with_quadrature(size, samples);
  const auto mom = moments_table(ltc_grid(size), options(samples));
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const auto ref = reference_moments(mom.grid.nov[i], mom.grid.alpha[j]);
      const auto& c = mom.cells[mom.grid.index(i, j)];
      m.n_d = std::max(m.n_d, std::abs(c[Term::One] - ref.n_d));
      m.f_d = std::max(m.f_d, std::abs(c[Term::Schlick] - ref.f_d));
      m.l_d = std::max(m.l_d, std::abs(c[Term::F82] - ref.l_d));
    }
  return m;
}

TEST(Lut, TablesAgreeWithQuadrature) {
  const auto m = compare_with_quadrature(10, kLutSamples);
  std::printf(
      "max |table - quadrature| at 10x10: dfg1 %.3g, dfg2 %.3g, dfg_f82 %.3g, n_d %.3g, f_d %.3g, "
      "l_d %.3g\n",
      m.dfg1, m.dfg2, m.dfg_f82, m.n_d, m.f_d, m.l_d);
  EXPECT_LT(m.dfg1, kQuadratureTolerance);
  EXPECT_LT(m.dfg2, kQuadratureTolerance);
  EXPECT_LT(m.dfg_f82, kQuadratureTolerance);
  EXPECT_LT(m.n_d, kQuadratureTolerance);
  EXPECT_LT(m.f_d, kQuadratureTolerance);
  EXPECT_LT(m.l_d, kQuadratureTolerance);
}

// The DFG F82 channel ∫ μ(1 − μ)⁶ ρ cos over the full 64² table `lut dfg` writes by default, as
// `lut dfg` computes it (kLutSamples per texel), against the quadrature.
TEST(Lut, DfgF82ChannelAgreesWithQuadratureOnTheFull64Grid) {
  constexpr double kDfgF82Tolerance = 2e-3;
  const auto m = compare_dfg_with_quadrature(64, kLutSamples);
  std::printf("max |dfg_f82 - quadrature| at 64x64: %.3g (dfg1 %.3g, dfg2 %.3g)\n", m.dfg_f82,
              m.dfg1, m.dfg2);
  EXPECT_LT(m.dfg_f82, kDfgF82Tolerance);
}

// The basis term b_k(μ), k = 1..4, summed term by term in long double from the polynomial's
// coefficients (fresnel::basis_term evaluates it by Horner's rule in the centred variable).
double basis_reference(int k, double mu) {
  long double x = 2.0L * mu - 1.0L, sum = 0, power = 1;
  for (int i = 0; i <= fresnel::kBasisPolyDegree; ++i, power *= x)
    sum += static_cast<long double>(fresnel::kBasisPolyCentred[k - 1][i]) * power;
  return static_cast<double>(sum);
}

// The basis channels (dfg_b1..dfg_b4 in the DFG table, b1_d..b4_d in the LTC moments) over the
// full 64² tables `lut` writes by default, as `lut` computes them (kLutSamples per texel), against
// the quadrature: the tables are checked at the accuracy a renderer reads them with.
TEST(Lut, BasisChannelsAgreeWithQuadratureOnTheFull64Grids) {
  // Measured ≤ 2.0e-4 (the basis terms are of order 1, like 1 and (1 − μ)⁵).
  constexpr double kBasisChannelTolerance = 5e-4;
  constexpr Term kTerms[] = {Term::B1, Term::B2, Term::B3, Term::B4};
  const auto dfg = dfg_table(dfg_grid(64), options(kLutSamples));
  const auto mom = moments_table(ltc_grid(64), options(kLutSamples));
  double dfg_max[4] = {}, ltc_max[4] = {};
  auto compare = [&](const LutGrid& g, auto cell, double* max) {
    for (int j = 0; j < g.size; ++j)
      for (int i = 0; i < g.size; ++i) {
        const auto ref = test::reference_lobe_integrals(g.nov[i], g.alpha[j], [](double voh) {
          return Values{basis_reference(1, voh), basis_reference(2, voh), basis_reference(3, voh),
                        basis_reference(4, voh)};
        });
        for (int k = 0; k < 4; ++k)
          max[k] = std::max(max[k], std::abs(cell(g.index(i, j), kTerms[k]) - ref[k]));
      }
  };
  compare(
      dfg.grid, [&](int c, Term t) { return dfg.cells[c][t]; }, dfg_max);
  compare(
      mom.grid, [&](int c, Term t) { return mom.cells[c][t]; }, ltc_max);
  std::printf(
      "max |table - quadrature| at 64x64: dfg_b1..b4 %.3g %.3g %.3g %.3g, b1_d..b4_d %.3g %.3g "
      "%.3g %.3g\n",
      dfg_max[0], dfg_max[1], dfg_max[2], dfg_max[3], ltc_max[0], ltc_max[1], ltc_max[2],
      ltc_max[3]);
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(dfg_max[k], kBasisChannelTolerance) << k + 1;
    EXPECT_LT(ltc_max[k], kBasisChannelTolerance) << k + 1;
  }
}

TEST(Lut, DISABLED_FullTablesAgreeWithQuadrature) {
  const auto m = compare_with_quadrature(64, kLutSamples);
  std::printf(
      "max |table - quadrature| at 64x64: dfg1 %.3g, dfg2 %.3g, dfg_f82 %.3g, n_d %.3g, f_d %.3g, "
      "l_d %.3g\n",
      m.dfg1, m.dfg2, m.dfg_f82, m.n_d, m.f_d, m.l_d);
  EXPECT_LT(std::max({m.dfg1, m.dfg2, m.dfg_f82, m.n_d, m.f_d, m.l_d}), kQuadratureTolerance);
}

// ---- ltc_code's published fit (Heitz, Dupuy, Hill & Neubelt 2016; shared/testdata/ltc_code).

// fit/results/ltc.inc read by analysis/ltc/ltc_reference.h (its reader is tested in
// test_ltc_reference.cpp), in ltc_grid(64)'s cell order.
const LtcReferenceTable& ltc_code() {
  static const LtcReferenceTable t =
      read_ltc_code_table(std::string(FL_SHARED_TESTDATA) + "/ltc_code/ltc.inc");
  return t;
}

// ltc_code estimated n_D in float with stratified GGX-NDF samples (32 × 32 per cell): its values
// scatter about the quadrature here by up to ~1e-2 with alternating sign (measured 1.15e-2 max,
// mean difference −9.5e-4), so the check is both a bound per cell and a bound on the mean, which a
// systematic difference (another masking function, say) would break. The grazing row (n·v = 8e-4),
// where ltc_code's values sit 0.06 below, is left out; the quadrature and the table agree there.
TEST(Lut, NormMatchesLtcCode) {
  const auto& lc = ltc_code();
  const auto grid = ltc_grid(64);
  double worst = 0, sum = 0;
  int cells = 0;
  for (int t = 0; t < 63; t += 7)
    for (int a = 7; a < 64; a += 7) {
      const double diff =
          reference_moments(grid.nov[t], grid.alpha[a]).n_d - lc.magnitude[grid.index(t, a)];
      worst = std::max(worst, std::abs(diff));
      sum += diff;
      ++cells;
    }
  std::printf("n_D against ltc_code over %d cells: max |difference| %.3g, mean difference %.3g\n",
              cells, worst, sum / cells);
  EXPECT_LT(worst, kLtcCodeNormTolerance);
  EXPECT_LT(std::abs(sum / cells), kLtcCodeNormMeanTolerance);
}

// ---- LTC fits

// ∫ f over the sphere in the LTC frame's polar coordinates (θ from Z), panels in θ.
double integrate_sphere(const std::function<double(const brdf::Vec3&)>& f, double theta_end) {
  return test::integrate_sphere(
      [&](double x, double y, double z) {
        return f({x, y, z});
      },
      theta_end);
}

// Relative L3 distance (E₃/B₃)^⅓ between ρ cos and an approximation of it, over the sphere in polar
// coordinates about a frame's Z.
double relative_l3(const brdf::Vec3& v, double alpha, const LtcFrame& frame,
                   const std::function<double(const brdf::Vec3&)>& approx) {
  auto in_frame = [&](const std::function<double(const brdf::Vec3&)>& f) {
    return test::integrate_sphere(
        [&](double x, double y, double z) {
          return f({x * frame.x.x + y * frame.y.x + z * frame.z.x,
                    x * frame.x.y + y * frame.y.y + z * frame.z.y,
                    x * frame.x.z + y * frame.y.z + z * frame.z.z});
        },
        kPi, alpha);
  };
  const double e3 = in_frame([&](const brdf::Vec3& w) {
    return std::pow(std::abs(ref::lobe_cos(v, w, alpha) - approx(w)), 3);
  });
  const double b3 =
      in_frame([&](const brdf::Vec3& w) { return std::pow(ref::lobe_cos(v, w, alpha), 3); });
  return std::cbrt(e3 / b3);
}

// Relative L2 distance between ρ cos and an approximation of it, over the sphere.
double relative_l2(const brdf::Vec3& v, double alpha,
                   const std::function<double(const brdf::Vec3&)>& approx) {
  const double err2 = integrate_sphere(
      [&](const brdf::Vec3& w) {
        const double d = ref::lobe_cos(v, w, alpha) - approx(w);
        return d * d;
      },
      kPi);
  const double norm2 = integrate_sphere(
      [&](const brdf::Vec3& w) {
        const double b = ref::lobe_cos(v, w, alpha);
        return b * b;
      },
      kPi / 2);
  return std::sqrt(err2 / norm2);
}

// ltc_grid(8) samples the same axes as ltc_code's 64 × 64 table at every ninth cell (i/7 = 9i/63),
// so both fits can be judged on a metric neither minimizes: the relative L2 error against the GGX
// lobe by quadrature (both minimize Heitz's L3 error). The held-out error the table reports (256 +
// 256 fresh directions) against the relative L3 error of the same LTC by quadrature.
TEST(Ltc, FittedLobesIntegrateToOneAndMatchTheBrdfAsWellAsLtcCode) {
  constexpr int size = 8, kLtcCodeStride = 9;
  const auto& lc = ltc_code();
  const auto grid64 = ltc_grid(64);
  const auto t = fit_ltc_table(size, options(2048));
  int checked = 0;
  for (int j = size / 2; j < size; ++j)
    for (int i = 0; i < size; i += 2) {
      const int k = t.grid.index(i, j);
      const auto& c = t.cells[k];
      const auto& mo = t.moments[k];
      EXPECT_TRUE(c.fit.usable) << i << "," << j;
      const auto frame = i == 0 ? LtcFrame{} : ltc_frame_from_average_direction(mo.average_dir);
      // The normalized LTC over its support, the hemisphere ω·(−m31, 0, m11) > 0 of its frame.
      const double axis = std::hypot(c.params.m31, c.params.m11);
      const double unit = test::integrate_hemisphere_about(
          -c.params.m31 / axis, c.params.m11 / axis,
          [&](double x, double y, double z) { return ltc_density(c.params, x, y, z); });
      EXPECT_NEAR(unit, 1.0, kLtcUnitIntegralTolerance) << i << "," << j;

      const brdf::Vec3 v = brdf::view_from_nov(t.grid.nov[i]);
      const double alpha = t.grid.alpha[j];
      const double ours = relative_l2(v, alpha, [&](const brdf::Vec3& w) {
        const brdf::Vec3 f{brdf::dot(w, frame.x), brdf::dot(w, frame.y), brdf::dot(w, frame.z)};
        return mo[Term::One] * ltc_density(c.params, f.x, f.y, f.z);
      });
      const int lk = grid64.index(kLtcCodeStride * i, kLtcCodeStride * j);
      const double theirs = relative_l2(v, alpha, [&](const brdf::Vec3& w) {
        return lc.magnitude[lk] * ref::ltc_from_inverse(lc.m_inv[lk].m, w);
      });
      const double l3 = relative_l3(v, alpha, frame, [&](const brdf::Vec3& w) {
        return mo[Term::One] * ref::ltc_from_inverse(c.m_inv.m, w);
      });
      std::printf(
          "n.v %.3f alpha %.3f: relative L2 ours %.4f, ltc_code %.4f; relative L3 %.4f (held-out "
          "estimate %.4f)\n",
          t.grid.nov[i], alpha, ours, theirs, l3, c.fit_error);
      EXPECT_LT(ours, theirs * kLobeAgainstLtcCodeRatio) << i << "," << j;
      EXPECT_NEAR(c.fit_error, l3, kFitErrorEstimateTolerance * l3) << i << "," << j;
      ++checked;
    }
  EXPECT_EQ(checked, 16);
}

// The ltc_1 texture as a shader reads it (ltc_code's GLSL: mat3(vec3(t.x, 0, t.y), vec3(0, 1, 0),
// vec3(t.z, 0, t.w)), columns) must give the fitted lobe: evaluated with eq. 3 from the four
// texture entries, it equals the fit's density in its own frame, direction by direction.
TEST(Ltc, TextureEntriesReproduceTheFittedLobe) {
  const auto t = fit_ltc_table(4, options(512));
  for (size_t k = 0; k < t.cells.size(); ++k) {
    const auto& c = t.cells[k];
    const int i = static_cast<int>(k) % t.grid.size;
    // M · M⁻¹ = I.
    for (int r = 0; r < 3; ++r)
      for (int q = 0; q < 3; ++q) {
        double s = 0;
        for (int n = 0; n < 3; ++n) s += c.m(r, n) * c.m_inv(n, q);
        EXPECT_NEAR(s, r == q ? 1.0 : 0.0, 1e-9);
      }
    const auto& p = c.inv_packed;
    const std::array<double, 9> shader_minv{p[0], 0, p[2], 0, 1, 0, p[1], 0, p[3]};  // row-major
    const auto frame =
        i == 0 ? LtcFrame{} : ltc_frame_from_average_direction(t.moments[k].average_dir);
    for (int a = 0; a < 12; ++a)
      for (int b = 0; b < 6; ++b) {
        const double theta = (b + 0.5) * kPi / 12, phi = (a + 0.5) * kPi / 6;
        const brdf::Vec3 w{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                           std::cos(theta)};
        const brdf::Vec3 f{brdf::dot(w, frame.x), brdf::dot(w, frame.y), brdf::dot(w, frame.z)};
        const double fitted = ltc_density(c.params, f.x, f.y, f.z);
        EXPECT_NEAR(ref::ltc_from_inverse(shader_minv, w), fitted,
                    kTextureDensityTolerance * std::max(1.0, fitted))
            << "cell " << k << " direction " << a << "," << b;
      }
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
                  return std::max(0.0, std::cos(omega) * std::cos(rho) +
                                           std::sin(omega) * std::sin(rho) * std::cos(psi));
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
      EXPECT_NEAR(horizon_clipped_sphere_form_factor(z, len), reference_form_factor(z, len),
                  kFormFactorTolerance)
          << z << "," << len;
  EXPECT_DOUBLE_EQ(horizon_clipped_sphere_form_factor(0.5, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(horizon_clipped_sphere_form_factor(-0.5, 0.0), 0.0);
}

}  // namespace
}  // namespace fl::analysis
