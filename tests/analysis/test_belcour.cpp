// The peer basis of Belcour, Bati & Barla 2020 (analysis/basis/belcour.cpp) against properties its
// construction implies, checked with an independent Fresnel formula and power iteration; and the
// rendered measure's lobe integrals against the LTC moments' own integrator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "analysis/basis/basis.h"
#include "analysis/basis/basis_rendered.h"
#include "analysis/lut/lut_accuracy.h"

namespace fl::analysis {
namespace {

using Vec = std::vector<double>;

// Orthogonality of singular vectors: sums of 1000 products of order 1.
constexpr double kOrthogonal = 1e-10;
// A leading eigenvector found by the eigensolver is a fixed point of the Gram matrix up to
// roundoff of the 1000-term sums.
constexpr double kEigenResidual = 1e-9;
// Lobe integrals of polynomials by the truth's 513 nodes against the moments' integrator.
constexpr double kLobeIntegral = 1e-3;

double dot(const Vec& a, const Vec& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// Unpolarized Fresnel reflectance of n + iκ from air, by the complex amplitudes (Born & Wolf).
double fresnel_amplitudes(double mu, std::complex<double> n) {
  const std::complex<double> n_cos_t = std::sqrt(n * n - (1.0 - mu * mu));  // n·cos θ_t
  const auto rs = (mu - n_cos_t) / (mu + n_cos_t);
  const auto rp = (n * n * mu - n_cos_t) / (n * n * mu + n_cos_t);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

const PeerBasis& peer() {
  static const PeerBasis b = belcour_basis(3);
  return b;
}

TEST(Belcour, FunctionsAreScaledAsTheyScaleThem) {
  const auto& b = peer();
  ASSERT_EQ(b.functions.size(), 5u);
  ASSERT_EQ(b.mu.size(), size_t(kBelcourSamples));
  for (double v : b.functions[0]) EXPECT_EQ(v, 1.0);
  EXPECT_DOUBLE_EQ(*std::max_element(b.functions[1].begin(), b.functions[1].end()), 1.0);
  EXPECT_GE(*std::min_element(b.functions[1].begin(), b.functions[1].end()), 0.0);
  for (size_t k = 2; k < 5; ++k) {
    double peak = 0;
    for (double v : b.functions[k]) peak = std::max(peak, std::abs(v));
    EXPECT_DOUBLE_EQ(peak, 1.0) << k;
  }
}

// b2, b3, b4 are right singular vectors of one stack: orthogonal under the plain sum.
TEST(Belcour, SecondStackVectorsAreOrthogonal) {
  const auto& f = peer().functions;
  for (size_t a = 2; a < 5; ++a)
    for (size_t c = a + 1; c < 5; ++c)
      EXPECT_LT(std::abs(dot(f[a], f[c])) / std::sqrt(dot(f[a], f[a]) * dot(f[c], f[c])),
                kOrthogonal)
          << a << " " << c;
}

// The normalized curves rebuilt here with the amplitude formula: b1 (up to scale) is the Gram
// matrix's leading eigenvector, so Σ_c (f_c·b1) f_c is parallel to b1 and its Rayleigh quotient
// exceeds Schlick's (1 − μ)⁵'s, the obvious rival shape.
TEST(Belcour, B1IsTheLeadingSingularVectorOfTheNormalizedCurves) {
  const auto& b = peer();
  std::vector<Vec> curves;
  auto add = [&](std::complex<double> n) {
    const double f0 = fresnel_amplitudes(1.0, n);
    Vec f;
    for (double m : b.mu) f.push_back((fresnel_amplitudes(m, n) - f0) / (1 - f0));
    curves.push_back(std::move(f));
  };
  add({1.1, 0.0});
  for (int k = 1; k <= kBelcourConductors; ++k) {
    const double r = std::min(double(k) / kBelcourConductors, kBelcourMaxReflectivity);
    const double eta = (1 - r) / (1 + r);
    add({eta, std::sqrt((r * (1 + eta) * (1 + eta) - (eta - 1) * (eta - 1)) / (1 - r))});
  }
  const int dielectrics = kBelcourCurves - 1 - kBelcourConductors;
  for (int k = 0; k < dielectrics; ++k)
    add({1.01 + 1.99 * double(k + 1) / (kBelcourCurves - kBelcourConductors), 0.0});
  auto gram_times = [&](const Vec& v) {
    Vec out(v.size(), 0.0);
    for (const auto& f : curves) {
      const double c = dot(f, v);
      for (size_t j = 0; j < v.size(); ++j) out[j] += c * f[j];
    }
    return out;
  };
  const Vec& b1 = b.functions[1];
  const Vec g = gram_times(b1);
  const double rayleigh = dot(b1, g) / dot(b1, b1);
  double off = 0;
  for (size_t j = 0; j < g.size(); ++j) off = std::max(off, std::abs(g[j] - rayleigh * b1[j]));
  EXPECT_LT(off / std::sqrt(dot(g, g)), kEigenResidual);
  Vec schlick;
  for (double m : b.mu) schlick.push_back(std::pow(1 - m, 5));
  EXPECT_GT(rayleigh, dot(schlick, gram_times(schlick)) / dot(schlick, schlick));
}

// Their projection reproduces a curve exactly at normal incidence and at its two angles.
TEST(Belcour, TwoPointProjectionIsExactAtItsAngles) {
  const auto& b = peer();
  for (const std::complex<double> n : {std::complex<double>(1.5, 0), {0.2, 3.4}, {2.9, 3.0}}) {
    const auto at = [&](double m) { return fresnel_amplitudes(m, n); };
    const size_t i = b.two_point[0], j = b.two_point[1];
    const auto c = b.two_point_coefficients(at(1.0), at(b.mu[i]), at(b.mu[j]));
    auto model = [&](size_t s) {
      double v = 0;
      for (size_t k = 0; k < 4; ++k) v += c[k] * b.functions[k][s];
      return v;
    };
    EXPECT_NEAR(model(b.mu.size() - 1), at(1.0), 1e-12);
    EXPECT_NEAR(model(i), at(b.mu[i]), 1e-12);
    EXPECT_NEAR(model(j), at(b.mu[j]), 1e-12);
  }
}

// The rendered measure integrates a function over the lobe by the truth's own quadrature: for
// 1, (1 − μ)⁵ and μ(1 − μ)⁶ that is Hill's n_D, f_D and the F82 moment at the point.
TEST(BasisRendered, LobeIntegralsMatchTheMoments) {
  const auto nodes = truth_nodes();
  std::vector<Vec> set(3);
  for (double m : nodes) {
    set[0].push_back(1.0);
    set[1].push_back(std::pow(1 - m, 5));
    set[2].push_back(m * std::pow(1 - m, 6));
  }
  const auto r = rendered_sets({set}, lut_accuracy_points());
  double worst = 0;
  for (size_t p = 0; p < r.points.size(); ++p) {
    const auto& moments = r.points[p].ltc_exact;
    const double exact[3] = {moments[fresnel::Term::One], moments[fresnel::Term::Schlick],
                             moments[fresnel::Term::F82]};
    for (int t = 0; t < 3; ++t) worst = std::max(worst, std::abs(r.integrals[0][t][p] - exact[t]));
  }
  EXPECT_LT(worst, kLobeIntegral);
  RecordProperty("largest_difference", std::to_string(worst));
}

}  // namespace
}  // namespace fl::analysis
