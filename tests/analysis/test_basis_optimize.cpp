// The optimized basis's surrogate (analysis/basis/optimize_surrogate.h) against independent
// computations: with G = I a page's squared error is the mean squared residual of its per-channel
// least-squares projection (Projector, QR); the analytic gradient against central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/basis/basis.h"
#include "analysis/basis/optimize_surrogate.h"

namespace fl::analysis {
namespace {

using Eigen::MatrixXd;

constexpr int kAngles = 91;

// Deterministic values in [0, 1).
double pseudo_random(unsigned& state) {
  state = state * 1664525u + 1013904223u;
  return (state >> 8) / 16777216.0;
}

// Smooth curves per channel (a + b(1 − μ)^p + c μ), a symmetric positive definite G per angle.
std::vector<SurrogatePage> synthetic_pages(int count, int metals, bool identity_gram) {
  const auto mu = basis_mu_samples(kAngles);
  unsigned state = 7;
  std::vector<SurrogatePage> pages(static_cast<size_t>(count));
  for (int p = 0; p < count; ++p) {
    auto& page = pages[static_cast<size_t>(p)];
    page.metal = p < metals;
    page.truth.resize(kAngles, 3);
    for (int c = 0; c < 3; ++c) {
      const double a = pseudo_random(state), b = pseudo_random(state),
                   power = 3 + 6 * pseudo_random(state), slope = 0.2 * pseudo_random(state);
      for (int j = 0; j < kAngles; ++j)
        page.truth(j, c) = a + b * std::pow(1 - mu[j], power) + slope * mu[j];
    }
    for (int j = 0; j < kAngles; ++j) {
      if (identity_gram) {
        page.gram.push_back({1, 0, 0, 1, 0, 1});
        continue;
      }
      double m[3][3];
      for (auto& row : m)
        for (double& v : row) v = pseudo_random(state) - 0.5;
      auto g = [&](int r, int c) {
        return m[0][r] * m[0][c] + m[1][r] * m[1][c] + m[2][r] * m[2][c] + (r == c ? 0.1 : 0.0);
      };
      page.gram.push_back({g(0, 0), g(0, 1), g(0, 2), g(1, 1), g(1, 2), g(2, 2)});
    }
  }
  return pages;
}

// [1, b1, b2, b3]: low-order polynomials, not orthogonal.
MatrixXd test_basis() {
  const auto mu = basis_mu_samples(kAngles);
  MatrixXd b(kAngles, 4);
  for (int j = 0; j < kAngles; ++j) {
    const double x = 2 * mu[j] - 1;
    b.row(j) << 1, std::pow(1 - mu[j], 5), x * x - 0.3 * x, x * x * x + 0.2;
  }
  return b;
}

TEST(BasisSurrogate, WithUnitGramIsTheMeanSquaredResidualOfTheProjection) {
  const auto pages = synthetic_pages(6, 3, true);
  const MatrixXd b = test_basis();
  std::vector<std::vector<double>> functions(4);
  for (int k = 0; k < 4; ++k) functions[k].assign(b.col(k).data(), b.col(k).data() + kAngles);
  const Projector projector(functions);
  const auto e = Surrogate(pages, nested_objective()).errors(b);
  for (size_t p = 0; p < pages.size(); ++p) {
    double sum2 = 0;
    for (int c = 0; c < 3; ++c) {
      const std::vector<double> f(pages[p].truth.col(c).data(),
                                  pages[p].truth.col(c).data() + kAngles);
      for (double r : projector.residual(f)) sum2 += r * r;
    }
    EXPECT_NEAR(e[p], std::sqrt(sum2 / kAngles), 1e-12) << "page " << p;
  }
}

// Every term of the objective active: targets at zero, so the tail, the ranks and the dielectrics'
// median band all contribute.
BasisObjective every_term_active() {
  BasisObjective o;
  o.tail_from = 0;
  o.metal_rank_target = 0;
  o.dielectric_median_target = 0;
  o.band = 3;
  return o;
}

TEST(BasisSurrogate, GradientMatchesCentralDifferences) {
  const auto pages = synthetic_pages(40, 15, false);
  const MatrixXd b = test_basis();
  constexpr int kFree = 3;
  for (const auto& objective : {nested_objective(), every_term_active()}) {
    const Surrogate s(pages, objective);
    MatrixXd gradient;
    s.value(b, kFree, &gradient);
    ASSERT_EQ(gradient.rows(), kAngles);
    ASSERT_EQ(gradient.cols(), kFree);
    constexpr double kStep = 1e-6;
    double worst = 0, scale = 0;
    for (int f = 0; f < kFree; ++f)
      for (int j = 0; j < kAngles; j += 9) {
        MatrixXd up = b, down = b;
        up(j, 1 + f) += kStep;
        down(j, 1 + f) -= kStep;
        const double numeric =
            (s.value(up, kFree, nullptr) - s.value(down, kFree, nullptr)) / (2 * kStep);
        worst = std::max(worst, std::abs(numeric - gradient(j, f)));
        scale = std::max(scale, std::abs(numeric));
      }
    // Central differences of a smooth function: error O(h²) plus rounding of O(1e-16/h).
    EXPECT_GT(scale, 1e-4);
    EXPECT_LT(worst, 1e-6 * scale) << "largest |numeric − analytic| " << worst;
  }
}

}  // namespace
}  // namespace fl::analysis
