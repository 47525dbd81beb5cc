// Numerical stability of the Fresnel kernels on hard cases: exact 0° and 90°, κ ≫ η, η < 1,
// Gulbrandsen's singular points, total internal reflection, η_E > η, dense parameter sweeps with
// no NaN/Inf and results in [0, 1], float against double.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "fresnel/exact.h"
#include "fresnel/media.h"
#include "fresnel/registry.h"

namespace {

using namespace fl::fresnel;

constexpr double kPi = 3.14159265358979323846;
double deg_to_cos(double deg) {
  return deg == 90.0 ? 0.0 : std::cos(deg * kPi / 180.0);
}

// Tolerances.
constexpr double kExact = 1e-12;             // closed forms evaluated in double
constexpr double kRangeSlackDouble = 1e-12;  // rounding allowed past [0, 1] in double
constexpr double kRangeSlackFloat = 1e-6;    // ... in float
constexpr double kFloatPolynomial =
    1e-6;  // float vs double: Schlick-type polynomials (measured 2.7e-7)
constexpr double kFloatFresnel =
    5e-6;  // float vs double: exact Fresnel, Gulbrandsen, Cook-Torrance (3.6e-6)
constexpr double kFloatCookTorranceKappa80 = 2e-4;  // ... Cook-Torrance with κ_rep = 80 (6.4e-5)
constexpr double kFloatGulbrandsenEta =
    5e-3;  // float vs double: η from F0 near 1 (relative; 1.4e-3)
constexpr double kFloatGulbrandsenG =
    2e-3;  // float vs double: g recovered from float η, F0 < 0.99 (9.4e-4)

// Dense grids: F0, g, F82 in [0, 1]; η in [0.01, 10]; κ in [0, 80]; θ in [0°, 90°].
std::vector<double> unit_grid() {
  std::vector<double> v;
  for (int i = 0; i <= 50; ++i) v.push_back(i / 50.0);
  v.push_back(1e-9);
  v.push_back(1.0 - 1e-9);
  return v;
}
std::vector<double> eta_grid() {  // log-spaced, with 1 (index-matched) exactly
  std::vector<double> v;
  for (int i = 0; i <= 60; ++i) v.push_back(0.01 * std::pow(1000.0, i / 60.0));
  v.push_back(1.0);
  v.push_back(10.0);
  return v;
}
std::vector<double> kappa_grid() {  // 0, then log-spaced 1e-4..80
  std::vector<double> v{0.0};
  for (int i = 0; i <= 40; ++i) v.push_back(1e-4 * std::pow(80.0 / 1e-4, i / 40.0));
  v.push_back(80.0);
  return v;
}
std::vector<double> cos_grid() {  // θ = 0°, 0.5°, ..., 90° (cos 90° = 0 exactly)
  std::vector<double> v;
  for (int i = 0; i <= 180; ++i) v.push_back(deg_to_cos(0.5 * i));
  return v;
}

// Counts values that are NaN/Inf or outside [0, 1] by more than the slack.
struct RangeCheck {
  double slack;
  long non_finite = 0, outside = 0, total = 0;
  double min = std::numeric_limits<double>::infinity(),
         max = -std::numeric_limits<double>::infinity();
  void operator()(double v) {
    ++total;
    if (!std::isfinite(v)) {
      ++non_finite;
      return;
    }
    min = std::min(min, v);
    max = std::max(max, v);
    if (v < -slack || v > 1.0 + slack) ++outside;
  }
};

// Normal-incidence reflectance of a conductor: ((η − 1)² + κ²) / ((η + 1)² + κ²).
double f0_exact(double eta, double kappa) {
  return ((eta - 1) * (eta - 1) + kappa * kappa) / ((eta + 1) * (eta + 1) + kappa * kappa);
}

// ---------------- exact Fresnel ----------------

TEST(HardCases, ConductorAtNormalAndGrazingIncidenceOverTheWholeGrid) {
  for (double eta : eta_grid())
    for (double kappa : kappa_grid()) {
      EXPECT_NEAR(fresnel_conductor(1.0, eta, kappa), f0_exact(eta, kappa), kExact)
          << eta << " " << kappa;
      // Grazing incidence reflects fully, except on an index-matched interface (η = 1, κ = 0),
      // which is no interface and reflects nothing at any angle (was 0/0 = NaN).
      const double grazing = eta == 1.0 && kappa == 0.0 ? 0.0 : 1.0;
      EXPECT_EQ(fresnel_conductor(0.0, eta, kappa), grazing) << eta << " " << kappa;
      const float grazing_f = float(eta) == 1.0f && float(kappa) == 0.0f ? 0.0f : 1.0f;
      EXPECT_EQ(fresnel_conductor(0.0f, float(eta), float(kappa)), grazing_f)
          << eta << " " << kappa;
    }
}

TEST(HardCases, IndexMatchedInterfaceReflectsNothingBeforeGrazing) {
  for (double c : cos_grid()) {
    if (c > 0.0) {
      EXPECT_NEAR(fresnel_conductor(c, 1.0, 0.0), 0.0, kExact) << c;
    }
  }
}

TEST(HardCases, KappaFarAboveEta) {
  // η = 0.01, κ = 80: F0 = (0.99² + 6400)/(1.01² + 6400); the curve stays in [F0·(1 − 1e-3), 1].
  const double f0 = f0_exact(0.01, 80.0);
  EXPECT_NEAR(fresnel_conductor(1.0, 0.01, 80.0), f0, kExact);
  for (double c : cos_grid()) {
    const double f = fresnel_conductor(c, 0.01, 80.0);
    ASSERT_TRUE(std::isfinite(f)) << c;
    EXPECT_GE(f, f0 * (1.0 - 1e-3)) << c;
    EXPECT_LE(f, 1.0) << c;
    EXPECT_NEAR(fresnel_conductor(float(c), 0.01f, 80.0f), f, kFloatFresnel) << c;
  }
}

TEST(HardCases, EtaBelowOneSilverLike) {
  // Silver near 550 nm: η ≈ 0.059, κ ≈ 3.59; F0 ≈ 0.98, rising monotonically... to 1 at 90°
  // after a shallow dip (p-polarization's pseudo-Brewster angle).
  const double eta = 0.059, kappa = 3.59;
  EXPECT_NEAR(fresnel_conductor(1.0, eta, kappa), f0_exact(eta, kappa), kExact);
  EXPECT_GT(f0_exact(eta, kappa), 0.98);
  for (double c : cos_grid()) {
    const double f = fresnel_conductor(c, eta, kappa);
    EXPECT_GE(f, 0.95) << c;
    EXPECT_LE(f, 1.0) << c;
  }
}

TEST(HardCases, TotalInternalReflection) {
  // κ = 0 and η < 1 (glass → air, η = 1/1.5): F = 1 past the critical angle asin(η); before it
  // the conductor form equals the dielectric Fresnel equations.
  const double eta = 1.0 / 1.5;
  const double critical_deg = std::asin(eta) * 180.0 / kPi;  // 41.81°
  EXPECT_NEAR(critical_deg, 41.8103, 1e-4);
  for (int i = 0; i <= 180; ++i) {
    const double deg = 0.5 * i, c = deg_to_cos(deg);
    const double fc = fresnel_conductor(c, eta, 0.0), fd = fresnel_dielectric(c, eta);
    if (deg > critical_deg) {
      EXPECT_NEAR(fc, 1.0, kExact) << deg;
      EXPECT_EQ(fd, 1.0) << deg;
      EXPECT_EQ(cos_transmitted(c, eta), 0.0) << deg;
    } else {
      EXPECT_NEAR(fc, fd, 1e-9) << deg;
      EXPECT_LT(fd, 1.0) << deg;
    }
  }
  // Exactly at the critical angle the refracted ray grazes: full reflection in both forms.
  const double cc = std::sqrt(1.0 - eta * eta);
  EXPECT_NEAR(fresnel_dielectric(cc, eta), 1.0, 1e-6);
  EXPECT_NEAR(fresnel_conductor(cc, eta, 0.0), 1.0, 1e-6);
}

TEST(HardCases, DielectricMatchesConductorWithZeroKappaOverTheEtaGrid) {
  for (double eta : eta_grid())
    for (double c : cos_grid()) {
      const double fd = fresnel_dielectric(c, eta), fc = fresnel_conductor(c, eta, 0.0);
      ASSERT_TRUE(std::isfinite(fd)) << eta << " " << c;
      EXPECT_NEAR(fd, fc, 1e-9) << eta << " " << c;
    }
}

TEST(HardCases, ExternalMediumDenserThanTheMaterial) {
  // η_E > η: glass (1.5) under a medium of 2.0 is an η = 0.75 interface: TIR past 48.59°; the
  // symmetric F0 re-expression gives ((1.5 − 2)/(1.5 + 2))² = 0.020408.
  const double n = 1.5;
  const double f0_air = f0_exact(n, 0.0);
  for (double eta_e : {1.0, 1.33, 1.5, 2.0, 3.0, 10.0}) {
    const double want = ((n - eta_e) / (n + eta_e)) * ((n - eta_e) / (n + eta_e));
    EXPECT_NEAR(f0_in_medium_symmetric(f0_air, eta_e), want, kExact) << eta_e;
    EXPECT_NEAR(fresnel_dielectric(1.0, n / eta_e), want, kExact) << eta_e;
  }
  EXPECT_NEAR(f0_in_medium_symmetric(f0_air, 2.0), 0.0204082, 1e-7);
  EXPECT_NEAR(f0_in_medium_symmetric(f0_air, 1.5), 0.0, kExact);  // index-matched: no reflection
  EXPECT_EQ(fresnel_dielectric(deg_to_cos(50.0), n / 2.0), 1.0);
  EXPECT_LT(fresnel_dielectric(deg_to_cos(48.0), n / 2.0), 1.0);
  // Never NaN over the grid, F0 in [0, 1].
  for (double f0 : unit_grid())
    for (double eta_e : eta_grid()) {
      const double r = f0_in_medium_symmetric(f0, eta_e);
      ASSERT_TRUE(std::isfinite(r)) << f0 << " " << eta_e;
      EXPECT_GE(r, 0.0);
      EXPECT_LE(r, 1.0 + kRangeSlackDouble) << f0 << " " << eta_e;
    }
}

TEST(HardCases, ExactFresnelSweepStaysFiniteAndInUnitRange) {
  RangeCheck cd{kRangeSlackDouble}, cf{kRangeSlackFloat}, dd{kRangeSlackDouble};
  for (double eta : eta_grid())
    for (double c : cos_grid()) {
      dd(fresnel_dielectric(c, eta));
      for (double kappa : kappa_grid()) {
        cd(fresnel_conductor(c, eta, kappa));
        cf(fresnel_conductor(float(c), float(eta), float(kappa)));
      }
    }
  for (const RangeCheck* r : {&cd, &cf, &dd}) {
    EXPECT_EQ(r->non_finite, 0);
    EXPECT_EQ(r->outside, 0) << "min " << r->min << " max " << r->max;
    EXPECT_GT(r->total, 10000);
  }
}

// ---------------- approximate models ----------------

TEST(HardCases, SchlickAndGeneralizedSchlickSweep) {
  RangeCheck s{kRangeSlackDouble}, gs{kRangeSlackDouble};
  for (double f0 : unit_grid())
    for (double c : cos_grid()) {
      s(schlick(c, f0));
      for (double f90 : {0.0, 0.5, 1.0})
        for (double p : {0.25, 1.0, 5.0, 20.0}) gs(generalized_schlick(c, f0, f90, p));
    }
  EXPECT_EQ(s.non_finite + s.outside, 0);
  EXPECT_EQ(gs.non_finite + gs.outside, 0);
  // The ends: F0 at 0°, 1 (or F90) at 90°.
  EXPECT_EQ(schlick(1.0, 0.04), 0.04);
  EXPECT_EQ(schlick(0.0, 0.04), 1.0);
  EXPECT_EQ(generalized_schlick(1.0, 0.04, 0.7, 5.0), 0.04);
  EXPECT_NEAR(generalized_schlick(0.0, 0.04, 0.7, 5.0), 0.7, kExact);
  // p = 5, F90 = 1 is Schlick.
  for (double c : cos_grid())
    EXPECT_NEAR(generalized_schlick(c, 0.3, 1.0, 5.0), schlick(c, 0.3), kExact);
}

TEST(HardCases, LazanyiIsFiniteAndLeavesUnitRangeOnlyThroughItsCorrectionTerm) {
  // With arbitrary a the correction can push F outside [0, 1]: that is the model, flagged here.
  RangeCheck r{kRangeSlackDouble};
  for (double f0 : unit_grid())
    for (double c : cos_grid())
      for (double a : {-10.0, -1.0, 0.0, 1.0, 10.0})
        for (double alpha : {0.5, 1.0, 6.0, 12.0}) {
          const double f = lazanyi(c, f0, a, alpha);
          r(f);
          if (a == 0.0) {
            EXPECT_EQ(f, schlick(c, f0));
          }
        }
  EXPECT_EQ(r.non_finite, 0);
  EXPECT_GT(r.outside, 0);  // flagged: e.g. a = 10 at F0 = 0 goes negative
  EXPECT_LT(lazanyi(0.5, 0.0, 10.0, 1.0), 0.0);
  EXPECT_NEAR(lazanyi(0.5, 0.0, 10.0, 1.0), 0.03125 - 2.5, kExact);
}

TEST(HardCases, HoffmanF82ThroughItsAnchorsAndClampedIntoUnitRange) {
  RangeCheck clamped{0.0}, raw{kRangeSlackDouble};
  const double c82 = 1.0 / 7.0;  // cos 81.79°
  for (double f0 : unit_grid())
    for (double f82 : unit_grid()) {
      EXPECT_NEAR(hoffman_f82_unclamped(1.0, f0, f82), f0, kExact);
      EXPECT_NEAR(hoffman_f82_unclamped(0.0, f0, f82), 1.0, kExact);
      EXPECT_NEAR(hoffman_f82_unclamped(c82, f0, f82), f82, 1e-12);
      for (double c : cos_grid()) {
        const double u = hoffman_f82_unclamped(c, f0, f82), f = hoffman_f82(c, f0, f82);
        raw(u);
        clamped(f);
        if (u >= 0.0 && u <= 1.0) {
          EXPECT_EQ(f, u);
        }
      }
    }
  EXPECT_EQ(clamped.non_finite + clamped.outside, 0);
  EXPECT_EQ(raw.non_finite, 0);
  // Flagged: F0 = 0 with F82 = 1 overshoots (to 1.13 near 70°) before the clamp. The overshoot is
  // the published model's own: Hoffman 2019's F(μ) = F_Schlick(μ) − a μ (1 − μ)⁶ with a fixed by
  // F(1/7) = F82, a = (F_Schlick(1/7) − F82) / ((1/7)(6/7)⁶), maximized over the same sweep.
  EXPECT_GT(raw.outside, 0);
  double paper_max = 0;
  for (double f0 : unit_grid())
    for (double f82 : unit_grid()) {
      const double mb = 1.0 / 7.0;
      const double a = (f0 + (1 - f0) * std::pow(1 - mb, 5) - f82) / (mb * std::pow(1 - mb, 6));
      for (double c : cos_grid())
        paper_max =
            std::max(paper_max, f0 + (1 - f0) * std::pow(1 - c, 5) - a * c * std::pow(1 - c, 6));
    }
  EXPECT_GT(paper_max, 1.1);
  EXPECT_NEAR(raw.max, paper_max, kExact);
}

TEST(HardCases, GulbrandsenSingularPointsAndEdgeTintEnds) {
  // F0 → 0 and F0 → 1 are the mapping's singular points: r is clamped to [1e-9, 0.99999] and
  // the model then reproduces the clamped F0 at normal incidence.
  for (double g : unit_grid()) {
    const double eta0 = gulbrandsen_eta(0.0, g), eta1 = gulbrandsen_eta(1.0, g);
    ASSERT_TRUE(std::isfinite(eta0) && std::isfinite(eta1)) << g;
    EXPECT_TRUE(std::isfinite(gulbrandsen_kappa(0.0, eta0)));
    EXPECT_TRUE(std::isfinite(gulbrandsen_kappa(1.0, eta1)));
    EXPECT_NEAR(gulbrandsen(1.0, 0.0, g), 1e-9, 1e-12) << g;
    EXPECT_NEAR(gulbrandsen(1.0, 1.0, g), kGulbrandsenMaxR, 1e-9) << g;
    EXPECT_EQ(gulbrandsen(0.0, 0.0, g), 1.0) << g;
    EXPECT_EQ(gulbrandsen(0.0, 1.0, g), 1.0) << g;
  }
  // g = 1: η = n_min = (1 − r)/(1 + r); g = 0: η = n_max = (1 + √r)/(1 − √r) and κ = 0.
  for (double r : {0.04, 0.5, 0.9, 0.99}) {
    EXPECT_NEAR(gulbrandsen_eta(r, 1.0), (1 - r) / (1 + r), kExact);
    const double nmax = (1 + std::sqrt(r)) / (1 - std::sqrt(r));
    EXPECT_NEAR(gulbrandsen_eta(r, 0.0), nmax, kExact * nmax);
    EXPECT_NEAR(gulbrandsen_kappa(r, nmax), 0.0, 1e-5);
    for (double g : unit_grid()) {
      EXPECT_NEAR(gulbrandsen(1.0, r, g), r, 1e-9) << r << " " << g;
      EXPECT_NEAR(gulbrandsen_g(r, gulbrandsen_eta(r, g)), g, 1e-9) << r << " " << g;
    }
  }
}

TEST(HardCases, GulbrandsenAndCookTorranceSweep) {
  RangeCheck gb{kRangeSlackDouble}, ct{kRangeSlackDouble};
  for (double f0 : unit_grid())
    for (double c : cos_grid()) {
      for (double g : unit_grid()) gb(gulbrandsen(c, f0, g));
      for (double eta : {0.01, 0.2, 1.0, 1.5, 10.0})
        for (double kappa : {0.0, 1.0, 80.0}) ct(cook_torrance(c, f0, eta, kappa));
    }
  EXPECT_EQ(gb.non_finite, 0);
  EXPECT_EQ(gb.outside, 0) << gb.min << " " << gb.max;
  EXPECT_EQ(ct.non_finite, 0);
  EXPECT_EQ(ct.outside, 0) << ct.min << " " << ct.max;
  // Cook-Torrance keeps F0 at 0° and reaches 1 at 90°; an index-matched representative has no
  // Fresnel rise at all, so the curve stays at F0.
  EXPECT_NEAR(cook_torrance(1.0, 0.3, 0.2, 3.0), 0.3, kExact);
  EXPECT_NEAR(cook_torrance(0.0, 0.3, 0.2, 3.0), 1.0, kExact);
  EXPECT_EQ(cook_torrance(0.0, 0.3, 1.0, 0.0), 0.3);
  EXPECT_NEAR(cook_torrance(0.5, 0.3, 1.0, 0.0), 0.3, kExact);
}

// ---------------- float against double ----------------

// Largest |float − double| of a kernel over a grid of argument tuples.
double max_float_error(const std::vector<std::vector<double>>& args,
                       const std::function<double(const std::vector<double>&)>& as_double,
                       const std::function<float(const std::vector<float>&)>& as_float) {
  double worst = 0;
  for (const auto& a : args) {
    // Both precisions see the same (float-representable) arguments.
    std::vector<float> af(a.begin(), a.end());
    const std::vector<double> ad(af.begin(), af.end());
    const double d = as_double(ad), f = as_float(af);
    if (!std::isfinite(d) || !std::isfinite(f)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(d - f));
  }
  return worst;
}

std::vector<std::vector<double>> tuples(const std::vector<std::vector<double>>& axes) {
  std::vector<std::vector<double>> out{{}};
  for (const auto& axis : axes) {
    std::vector<std::vector<double>> next;
    for (const auto& t : out)
      for (double v : axis) {
        auto u = t;
        u.push_back(v);
        next.push_back(u);
      }
    out.swap(next);
  }
  return out;
}

TEST(HardCases, FloatAgreesWithDoubleForEveryModelKernel) {
  std::vector<double> cs, us;
  for (int i = 0; i <= 45; ++i) cs.push_back(deg_to_cos(2.0 * i));
  for (int i = 0; i <= 20; ++i) us.push_back(i / 20.0);
  const std::vector<double> etas{0.01, 0.05, 0.2, 0.5, 1.0, 1.5, 2.5, 5.0, 10.0};
  const std::vector<double> kappas{0.0, 0.01, 0.5, 2.0, 5.0, 20.0, 80.0};

  EXPECT_LE(max_float_error(
                tuples({cs, us}), [](auto& a) { return schlick(a[0], a[1]); },
                [](auto& a) { return schlick(a[0], a[1]); }),
            kFloatPolynomial);
  EXPECT_LE(max_float_error(
                tuples({cs, us, {0.0, 0.5, 1.0}, {0.5, 5.0, 12.0}}),
                [](auto& a) { return generalized_schlick(a[0], a[1], a[2], a[3]); },
                [](auto& a) { return generalized_schlick(a[0], a[1], a[2], a[3]); }),
            kFloatPolynomial);
  EXPECT_LE(max_float_error(
                tuples({cs, us, {-2.0, 0.0, 2.0}, {1.0, 6.0}}),
                [](auto& a) { return lazanyi(a[0], a[1], a[2], a[3]); },
                [](auto& a) { return lazanyi(a[0], a[1], a[2], a[3]); }),
            kFloatPolynomial);
  EXPECT_LE(max_float_error(
                tuples({cs, us, us}), [](auto& a) { return hoffman_f82(a[0], a[1], a[2]); },
                [](auto& a) { return hoffman_f82(a[0], a[1], a[2]); }),
            kFloatPolynomial);
  EXPECT_LE(
      max_float_error(
          tuples({cs, etas, kappas}), [](auto& a) { return fresnel_conductor(a[0], a[1], a[2]); },
          [](auto& a) { return fresnel_conductor(a[0], a[1], a[2]); }),
      kFloatFresnel);
  EXPECT_LE(max_float_error(
                tuples({cs, etas}), [](auto& a) { return fresnel_dielectric(a[0], a[1]); },
                [](auto& a) { return fresnel_dielectric(a[0], a[1]); }),
            kFloatFresnel);
  EXPECT_LE(max_float_error(
                tuples({cs, us, us}), [](auto& a) { return gulbrandsen(a[0], a[1], a[2]); },
                [](auto& a) { return gulbrandsen(a[0], a[1], a[2]); }),
            kFloatFresnel);
  EXPECT_LE(max_float_error(
                tuples({cs, us, {0.2, 1.0, 1.5}, {0.0, 0.5, 3.0, 5.0}}),
                [](auto& a) { return cook_torrance(a[0], a[1], a[2], a[3]); },
                [](auto& a) { return cook_torrance(a[0], a[1], a[2], a[3]); }),
            kFloatFresnel);
  // A representative κ = 80 makes 1 − F0' ≈ 6e-4, and (F' − F0')/(1 − F0') amplifies float
  // rounding.
  EXPECT_LE(max_float_error(
                tuples({cs, us, {0.2, 1.0, 1.5}, {80.0}}),
                [](auto& a) { return cook_torrance(a[0], a[1], a[2], a[3]); },
                [](auto& a) { return cook_torrance(a[0], a[1], a[2], a[3]); }),
            kFloatCookTorranceKappa80);
  // The Gulbrandsen mapping itself: η relative to its size (it reaches 4e5 as F0 → 1), g absolute.
  double worst_eta = 0, worst_g = 0;
  for (double r : us)
    for (double g : us) {
      const double ed = gulbrandsen_eta(r, g);
      const float ef = gulbrandsen_eta(float(r), float(g));
      worst_eta = std::max(worst_eta, std::abs(ed - ef) / ed);
      if (r < 0.99) worst_g = std::max(worst_g, std::abs(g - double(gulbrandsen_g(float(r), ef))));
    }
  EXPECT_LE(worst_eta, kFloatGulbrandsenEta);
  EXPECT_LE(worst_g, kFloatGulbrandsenG);
}

}  // namespace
