// Kulla–Conty's tables (analysis/lut/energy.h) against the independent quadrature of
// dfg_reference.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/lut/energy.h"
#include "dfg_reference.h"

namespace fl::analysis {
namespace {

// The lobe integrals at kLutSamples quasi-Monte Carlo points against Gauss–Legendre: the DFG
// tables' tolerance (test_lut.cpp, measured ≤ 2.5e-4 over 64 × 64).
constexpr double kQuadratureTolerance = 3e-4;
// E_avg at α = 1e-4 is 1 up to the mirror limit's O(α² log 1/α) and the grazing views' masking.
constexpr double kMirrorTolerance = 1e-5;

// 2∫₀¹ E(μ) μ dμ of the reference E = n_D by Gauss–Legendre on 8 equal panels of 16 nodes in μ.
double reference_average(double alpha) {
  const auto rule = test::gauss_legendre(16);
  constexpr int kPanels = 8;
  double sum = 0;
  for (int p = 0; p < kPanels; ++p)
    for (size_t k = 0; k < rule.x.size(); ++k) {
      const double mu = (p + 0.5 * (rule.x[k] + 1)) / kPanels;
      sum += rule.w[k] * 0.5 / kPanels * 2 * mu * test::reference_moments(mu, alpha).n_d;
    }
  return sum;
}

TEST(Energy, TableAgreesWithQuadrature) {
  const auto t = energy_table(dfg_grid(8));
  double max_e = 0, max_avg = 0;
  for (int j = 0; j < t.grid.size; ++j) {
    for (int i = 0; i < t.grid.size; ++i)
      max_e =
          std::max(max_e, std::abs(t.e[t.grid.index(i, j)] -
                                   test::reference_moments(t.grid.nov[i], t.grid.alpha[j]).n_d));
    max_avg = std::max(max_avg, std::abs(t.e_avg[j] - reference_average(t.grid.alpha[j])));
  }
  std::printf("max |table - quadrature| at 8x8: E %.3g, E_avg %.3g\n", max_e, max_avg);
  EXPECT_LT(max_e, kQuadratureTolerance);
  EXPECT_LT(max_avg, kQuadratureTolerance);
}

TEST(Energy, MirrorKeepsAllEnergy) {
  const auto points = lobe_disk_points(kLutSamples);
  EXPECT_NEAR(average_albedo(1e-4, points), 1.0, kMirrorTolerance);
}

TEST(Energy, RoughLobesLoseEnergyMonotonically) {
  const auto t = energy_table(dfg_grid(8));
  for (int j = 1; j < t.grid.size; ++j) EXPECT_LT(t.e_avg[j], t.e_avg[j - 1]) << j;
  // Single scattering loses about half the energy at α = 1 (Kulla & Conty 2017, fig. 2).
  EXPECT_GT(t.e_avg.back(), 0.4);
  EXPECT_LT(t.e_avg.back(), 0.6);
}

}  // namespace
}  // namespace fl::analysis
