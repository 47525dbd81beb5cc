// The dielectric energy table (analysis/lut/energy.h, dielectric_energy_table) against the
// independent quadrature of dfg_reference.h with the Fresnel equations written here in their angle
// form, and its analytic limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "analysis/lut/energy.h"
#include "dfg_reference.h"

namespace fl::analysis {
namespace {

using test::operator+, test::operator*;

// The lobe integrals at kLutSamples quasi-Monte Carlo points against Gauss–Legendre: the DFG and
// energy tables' tolerance (test_energy.cpp).
constexpr double kQuadratureTolerance = 3e-4;
// Inside (η < 1), F's square-root edge at the critical angle within the lobe adds to the
// quasi-Monte Carlo error.
constexpr double kQuadratureToleranceInside = 4e-4;
// At α = 1e-5 the lobe is a mirror: E_F(μ) = F(μ) up to the lobe's width (O(α) in v·h), except
// where F has its square-root edge (the critical angle inside a medium).
constexpr double kMirrorTolerance = 1e-4;
// At η = 1e6, 1 − F ≈ 2(c + 1/c)/η over the lobe's v·h = c.
constexpr double kLargeEtaTolerance = 1e-4;
// η = 1 + 1e-4: F0 = 2.5e-9, and the critical cone inside is v·h < 0.014.
constexpr double kNearOne = 1.0001;
constexpr double kNearOneTolerance = 1e-4;
// Linear interpolation in t = (F0/0.25)^¼ between the 16 slices of the default table, for n·v ≥
// 0.2 and α ≥ 0.1; inside, the critical angle moves with η. Smooth grazing cells are worse
// (docs/engines.md).
constexpr double kSliceInterpolationTolerance = 3e-3;
constexpr double kSliceInterpolationToleranceInside = 0.06;

// Born & Wolf §1.5.2 in the angle form (Fresnel's sine and tangent laws):
// r_s = sin²(θi − θt)/sin²(θi + θt), r_p = tan²(θi − θt)/tan²(θi + θt), sin θt = sin θi / η; total
// reflection past the critical angle; ((η − 1)/(η + 1))² at normal incidence.
double reference_fresnel(double cos_i, double eta) {
  if (eta == 1.0) return 0.0;
  const double theta_i = std::acos(std::clamp(cos_i, 0.0, 1.0));
  const double sin_t = std::sin(theta_i) / eta;
  if (sin_t >= 1.0) return 1.0;
  if (theta_i < 1e-7) return std::pow((eta - 1) / (eta + 1), 2);
  const double theta_t = std::asin(sin_t);
  const double rs = std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
  const double rp = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
  return 0.5 * (rs * rs + rp * rp);
}

// The cosine of v·h below which F(v·h, η) = 1 (η < 1), where F has a square-root edge; 0 for η ≥ 1.
double critical_cosine(double eta) {
  return eta < 1 ? std::sqrt(1 - eta * eta) : 0.0;
}

// E_F at four indices at once: dfg_reference.h's quadrature over half vectors (θ, φ), with panel
// edges where v·h crosses each critical cosine (in φ at every θ, and the θ where that curve meets
// φ = 0 or π), so the Gauss–Legendre panels never straddle Fresnel's edge.
test::Values reference_albedos(double nov, double alpha, const test::Values& etas) {
  constexpr double kPi = std::numbers::pi;
  static const test::GaussRule g_theta = test::gauss_legendre(16), g_phi = test::gauss_legendre(32);
  const double theta_v = std::acos(nov), sin_v = std::sin(theta_v);
  std::vector<double> breaks{0.5 * (kPi / 2 - theta_v)}, cuts;
  for (double eta : etas)
    if (const double c = critical_cosine(eta); c > 0) {
      cuts.push_back(c);
      for (double t : {theta_v - std::acos(c), theta_v + std::acos(c), std::acos(c) - theta_v})
        if (t > 0) breaks.push_back(t);
    }
  auto f_theta = [&](double theta) -> test::Values {
    const double ct = std::cos(theta), st = std::sin(theta);
    double phi_max = kPi;
    if (sin_v > 0) {
      const double c = -(nov / sin_v) * std::cos(2 * theta) / std::sin(2 * theta);
      phi_max = c <= -1 ? kPi : (c >= 1 ? 0 : std::acos(c));
    } else if (theta >= kPi / 4) {
      phi_max = 0;
    }
    if (phi_max <= 0) return test::Values{};
    std::vector<double> edges{0, phi_max};
    for (double c : cuts)
      if (sin_v * st > 0) {
        const double x = (c - nov * ct) / (sin_v * st);
        if (x > -1 && x < 1 && std::acos(x) < phi_max) edges.push_back(std::acos(x));
      }
    std::sort(edges.begin(), edges.end());
    const double d = test::ggx_ref::ndf(ct, alpha);
    auto f_phi = [&](double phi) -> test::Values {
      const double voh = sin_v * st * std::cos(phi) + nov * ct;
      const double nol = 2 * voh * ct - nov;
      if (nol <= 0 || voh <= 0) return test::Values{};
      const double w = d * test::ggx_ref::g2(nov, nol, alpha) * voh / nov;
      return w * test::Values{reference_fresnel(voh, etas[0]), reference_fresnel(voh, etas[1]),
                              reference_fresnel(voh, etas[2]), reference_fresnel(voh, etas[3])};
    };
    test::Values sum{};
    for (size_t k = 0; k + 1 < edges.size(); ++k)
      sum = sum + test::integrate_panel<test::Values>(f_phi, edges[k], edges[k + 1], g_phi);
    return (2 * st) * sum;
  };
  return test::integrate_theta<test::Values>(f_theta, 0.5 * (kPi / 2 + theta_v), alpha, breaks,
                                             g_theta);
}

// 2∫₀¹ g(μ) μ dμ by Gauss–Legendre on 4 equal panels of 16 nodes in μ between consecutive
// `breaks` (0, 1 and any kinks of g).
template <class V, class G>
V reference_average(G g, std::vector<double> breaks = {}) {
  const auto rule = test::gauss_legendre(16);
  constexpr int kPanels = 4;
  breaks.insert(breaks.end(), {0.0, 1.0});
  std::sort(breaks.begin(), breaks.end());
  V sum{};
  for (size_t b = 0; b + 1 < breaks.size(); ++b) {
    const double lo = breaks[b], width = (breaks[b + 1] - lo) / kPanels;
    for (int p = 0; p < kPanels && width > 0; ++p)
      for (size_t k = 0; k < rule.x.size(); ++k) {
        const double mu = lo + (p + 0.5 * (rule.x[k] + 1)) * width;
        sum = sum + (rule.w[k] * 0.5 * width * 2 * mu) * g(mu);
      }
  }
  return sum;
}

struct Difference {
  double e = 0, e_avg = 0;
};

// The largest |table − reference| over slices k0 and k0 + 1, outside and inside.
Difference compare_slices(const DielectricEnergyTable& t, size_t k0) {
  const auto& a = t.slices[k0];
  const auto& b = t.slices[k0 + 1];
  const test::Values etas{a.eta, 1 / a.eta, b.eta, 1 / b.eta};
  Difference d;
  const auto& g = t.grid;
  for (int j = 0; j < g.size; ++j) {
    for (int i = 0; i < g.size; ++i) {
      const auto ref = reference_albedos(g.nov[i], g.alpha[j], etas);
      const int c = g.index(i, j);
      for (double x :
           {a.e_out[c] - ref[0], a.e_in[c] - ref[1], b.e_out[c] - ref[2], b.e_in[c] - ref[3]})
        d.e = std::max(d.e, std::abs(x));
    }
    if (j % 2) continue;  // E_F,avg on every other row: the reference's μ integral is the cost
    const auto avg = reference_average<test::Values>(
        [&](double mu) { return reference_albedos(mu, g.alpha[j], etas); },
        {critical_cosine(etas[1]), critical_cosine(etas[3])});
    for (double x : {a.e_avg_out[j] - avg[0], a.e_avg_in[j] - avg[1], b.e_avg_out[j] - avg[2],
                     b.e_avg_in[j] - avg[3]})
      d.e_avg = std::max(d.e_avg, std::abs(x));
  }
  return d;
}

TEST(DielectricEnergy, TableAgreesWithQuadrature) {
  const auto t = dielectric_energy_table(dfg_grid(8), 4);
  Difference max;
  for (size_t k0 : {size_t{0}, size_t{2}}) {
    const auto d = compare_slices(t, k0);
    max.e = std::max(max.e, d.e);
    max.e_avg = std::max(max.e_avg, d.e_avg);
  }
  std::printf("max |table - quadrature| at 8x8, 4 slices, eta and 1/eta: E_F %.3g, E_F,avg %.3g\n",
              max.e, max.e_avg);
  EXPECT_LT(max.e, kQuadratureToleranceInside);
  EXPECT_LT(max.e_avg, kQuadratureTolerance);
}

TEST(DielectricEnergy, SlicesSpanOneToThree) {
  const auto t = dielectric_energy_table(dfg_grid(2), 4, {64, 0, {}});
  EXPECT_EQ(t.slices.front().eta, 1.0);
  EXPECT_NEAR(t.slices.back().eta, 3.0, 1e-12);
  // F0^¼ uniform: slice 1 of 4 at F0 = 0.25/81.
  EXPECT_NEAR(t.slices[1].f0, 0.25 / 81, 1e-15);
  for (const auto& s : t.slices) EXPECT_NEAR(reference_fresnel(1.0, s.eta), s.f0, 1e-12) << s.eta;
  // η = 1 is no interface: nothing is reflected, from either side.
  for (double e : t.slices.front().e_out) EXPECT_EQ(e, 0.0);
  for (double e : t.slices.front().e_in) EXPECT_EQ(e, 0.0);
}

TEST(DielectricEnergy, IndexNearOneReflectsAlmostNothing) {
  const auto points = lobe_disk_points(kLutSamples);
  // F → 0 as η → 1 everywhere but at grazing v·h (inside: within the critical angle's cone,
  // v·h < √(1 − 1/η²)).
  double max_out = 0, max_in = 0;
  for (double nov : {0.1, 0.5, 1.0})
    for (double alpha : {0.01, 0.25, 1.0}) {
      const auto e = dielectric_albedos(nov, alpha, {kNearOne, 1 / kNearOne}, points);
      max_out = std::max(max_out, e[0]);
      max_in = std::max(max_in, e[1]);
    }
  std::printf("eta = %g: max E_F %.3g outside, %.3g inside\n", kNearOne, max_out, max_in);
  EXPECT_LT(max_out, kNearOneTolerance);
  EXPECT_LT(max_in, kNearOneTolerance);
}

TEST(DielectricEnergy, SmoothSurfaceReflectsTheFresnelReflectance) {
  const auto t = dielectric_energy_table(dfg_grid(8), 4);
  double max_e = 0, max_avg = 0;
  for (const auto& s : t.slices) {
    for (int i = 0; i < t.grid.size; ++i) {
      const double mu = t.grid.nov[i];
      max_e = std::max({max_e, std::abs(s.e_out[t.grid.index(i, 0)] - reference_fresnel(mu, s.eta)),
                        std::abs(s.e_in[t.grid.index(i, 0)] - reference_fresnel(mu, 1 / s.eta))});
    }
    // F_avg outside and inside, and the identity 1 − F_avg(1/η) = (1 − F_avg(η))/η² (energy
    // conservation and reciprocity at a smooth interface).
    const double f_avg =
        reference_average<double>([&](double mu) { return reference_fresnel(mu, s.eta); });
    max_avg = std::max({max_avg, std::abs(s.e_avg_out[0] - f_avg),
                        std::abs(s.e_avg_in[0] - (1 - (1 - f_avg) / (s.eta * s.eta)))});
  }
  std::printf("roughness 0: max |E_F - F| %.3g, max |E_F,avg - F_avg| %.3g\n", max_e, max_avg);
  EXPECT_LT(max_e, kMirrorTolerance);
  EXPECT_LT(max_avg, kMirrorTolerance);
}

TEST(DielectricEnergy, LargeIndexApproachesTheLobeAlbedo) {
  const auto points = lobe_disk_points(kLutSamples);
  double max_d = 0;
  for (double nov : {0.1, 0.5, 1.0})
    for (double alpha : {0.01, 0.25, 1.0})
      max_d = std::max(max_d, std::abs(dielectric_albedos(nov, alpha, {1e6}, points)[0] -
                                       directional_albedo(nov, alpha, points)));
  std::printf("eta = 1e6: max |E_F - E| %.3g\n", max_d);
  EXPECT_LT(max_d, kLargeEtaTolerance);
}

// Midway between two slices of the default table (the engine's interpolation variable
// t = (F0/0.25)^¼ halfway), against the albedo at that index.
TEST(DielectricEnergy, LinearInTBetweenSlices) {
  const auto points = lobe_disk_points(kLutSamples);
  constexpr int kSlices = kDielectricSlices;
  double max_out = 0, max_in = 0;
  for (int k = 0; k + 1 < kSlices; ++k) {
    const double t_mid = (k + 0.5) / (kSlices - 1);
    const double a = eta_from_f0(dielectric_slice_f0(k, kSlices)),
                 m = eta_from_f0(kDielectricMaxF0 * std::pow(t_mid, 4)),
                 b = eta_from_f0(dielectric_slice_f0(k + 1, kSlices));
    for (double nov : {0.2, 0.5, 1.0})
      for (double alpha : {0.1, 0.25, 0.5, 1.0}) {
        const auto e = dielectric_albedos(nov, alpha, {a, m, b, 1 / a, 1 / m, 1 / b}, points);
        max_out = std::max(max_out, std::abs(0.5 * (e[0] + e[2]) - e[1]));
        max_in = std::max(max_in, std::abs(0.5 * (e[3] + e[5]) - e[4]));
      }
  }
  std::printf(
      "midway between slices (n.v >= 0.2, alpha >= 0.1): max error %.3g outside, %.3g "
      "inside\n",
      max_out, max_in);
  EXPECT_LT(max_out, kSliceInterpolationTolerance);
  EXPECT_LT(max_in, kSliceInterpolationToleranceInside);
}

}  // namespace
}  // namespace fl::analysis
