// The LTC table against ltc_code's published fit (analysis/ltc/ltc_reference.h; Heitz, Dupuy, Hill
// & Neubelt 2016, shared/testdata/ltc_code): the reader against values read off the file, and a fit
// on every third cell of ltc_code's grid judged against it on held-out error, cell by cell and at
// the midpoints where bilinear lookups mix neighbouring cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "analysis/ltc/ltc_reference.h"
#include "analysis/lut/lut.h"
#include "spectral/text_file.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::analysis {
namespace {

// Directions per strategy when comparing tables on held-out error, and samples of n_D at midpoints.
constexpr int kComparisonSamples = 2048;
constexpr int kComparisonMomentSamples = 4096;

LutOptions options(int samples) {
  LutOptions o;
  o.samples = samples;
  return o;
}

TEST(LtcCode, ReadsThePublishedTable) {
  const std::string path = std::string(FL_SHARED_TESTDATA) + "/ltc_code/ltc.inc";
  const auto ref = read_ltc_code_table(path);
  ASSERT_EQ(ref.size, 64);
  ASSERT_EQ(ref.m_inv.size(), 4096u);
  const auto grid = ltc_grid(64);
  // First entry of tabMinv (a = 0, t = 0): diag(50000.003906, 50000.003906, 1), i.e. M = diag(2e-5,
  // 2e-5, 1) for α = 1e-5; the last (a = t = 63), listed column-major: {0.600356, -0, -0.048692,
  // -0, 0.602532, -0, 0.029464, -0, 0.998814}, and its tabMagnitude 0.932164.
  const auto& first = ref.m_inv[grid.index(0, 0)];
  EXPECT_DOUBLE_EQ(first(0, 0), 50000.003906);
  EXPECT_DOUBLE_EQ(first(2, 2), 1.0);
  const auto& last = ref.m_inv[grid.index(63, 63)];
  EXPECT_DOUBLE_EQ(last(0, 0), 0.600356);
  EXPECT_DOUBLE_EQ(last(2, 0), -0.048692);
  EXPECT_DOUBLE_EQ(last(0, 2), 0.029464);
  EXPECT_DOUBLE_EQ(last(2, 2), 0.998814);
  EXPECT_DOUBLE_EQ(ref.magnitude[grid.index(63, 63)], 0.932164);
  // Cell a + 64 t is (i_nov = t, j_roughness = a): a = 1, t = 0 is the second line (M⁻¹₀₀ =
  // 1984.499756); a = 0, t = 1 the 65th, {49989.300781, -0, -0.022446, -0, 50011.960938, -0,
  // 1122.355225, -0, 0.999748}.
  EXPECT_DOUBLE_EQ(ref.m_inv[grid.index(0, 1)](0, 0), 1984.499756);
  EXPECT_DOUBLE_EQ(ref.m_inv[grid.index(1, 0)](1, 1), 50011.960938);
  EXPECT_DOUBLE_EQ(ref.m_inv[grid.index(1, 0)](2, 0), -0.022446);
  EXPECT_DOUBLE_EQ(ref.m_inv[grid.index(1, 0)](0, 2), 1122.355225);

  test::TempDir tmp;
  std::string text = spectral::read_text_file(path);
  const auto cut =
      tmp.file("cut.inc", text.substr(0, text.find("static const float tabMagnitude")));
  EXPECT_THROW(read_ltc_code_table(cut), InputError);
  std::string bad = text;
  bad.replace(bad.find("50000.003906"), 12, "5x000.003906");
  try {
    read_ltc_code_table(tmp.file("bad.inc", bad));
    ADD_FAILURE() << "no error for a malformed number";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.inc:4103:"), std::string::npos) << e.what();
  }
}

// The cells of ltc_grid(22) are every third cell of ltc_grid(64) (x = i/21 = 3i/63), so a 22 × 22
// fit compares cell by cell with ltc_code's published 64 × 64 table.
constexpr int kSubsetSize = 22, kSubsetStride = 3;
LtcReferenceTable every_third_cell(const LtcReferenceTable& ref) {
  LtcReferenceTable sub;
  sub.size = kSubsetSize;
  const auto g64 = ltc_grid(ref.size), g22 = ltc_grid(kSubsetSize);
  for (int j = 0; j < kSubsetSize; ++j)
    for (int i = 0; i < kSubsetSize; ++i) {
      EXPECT_NEAR(g22.nov[i], g64.nov[kSubsetStride * i], 1e-12);
      EXPECT_NEAR(g22.alpha[j], g64.alpha[kSubsetStride * j], 1e-12);
      sub.m_inv.push_back(ref.m_inv[g64.index(kSubsetStride * i, kSubsetStride * j)]);
      sub.magnitude.push_back(ref.magnitude[g64.index(kSubsetStride * i, kSubsetStride * j)]);
    }
  return sub;
}

struct SubsetComparison {
  LtcTable table;
  LtcComparison comparison;
};
const SubsetComparison& subset_comparison() {
  static const SubsetComparison c = [] {
    SubsetComparison out;
    out.table = fit_ltc_table(kSubsetSize, options(kLutSamples));
    const auto ref = every_third_cell(
        read_ltc_code_table(std::string(FL_SHARED_TESTDATA) + "/ltc_code/ltc.inc"));
    out.comparison =
        compare_ltc_tables(out.table, ref, kComparisonSamples, kComparisonMomentSamples);
    return out;
  }();
  return c;
}

TEST(LtcCode, FitIsNoWorseOutOfSample) {
  const auto& c = subset_comparison();
  for (const auto& b : c.comparison.bands) {
    EXPECT_LE(b.mean, b.reference_mean) << b.band;
    EXPECT_LE(b.max, b.reference_max) << b.band;
  }
  // Every cell of the grazing row, where the fit used to settle on thin lobes.
  const int n = c.table.grid.size;
  for (int j = 0; j < n; ++j) {
    const int k = c.table.grid.index(n - 1, j);
    EXPECT_LE(c.comparison.error[k], c.comparison.reference_error[k])
        << "roughness column " << kSubsetStride * j;
  }
}

// No texture entry steps between neighbouring cells of the 64 × 64 table by more than ltc_code's
// table does anywhere: per entry, the largest difference between neighbours against ltc_code's
// largest. The fit's optimum at the grazing row, roughness 1, steps by 0.14 in M⁻¹₂₂ from the row
// before (ltc_code's table by 0.10, its largest step of any entry); the near-equal choice there
// (kLtcGrazingNearEqualMargin) takes the continuation's 0.08. Moments with fewer samples than the
// shipped table's: the steps do not depend on them.
constexpr int kJumpMomentSamples = 2048;
TEST(LtcCode, NoEntryStepsBetweenNeighboursMoreThanLtcCodes) {
  const auto table = fit_ltc_table(64, options(kJumpMomentSamples));
  const auto ref = read_ltc_code_table(std::string(FL_SHARED_TESTDATA) + "/ltc_code/ltc.inc");
  for (const auto& j : ltc_entry_jumps(table, ref)) {
    std::printf("%s: largest step %.4f at (%d, %d), ltc_code %.4f at (%d, %d)\n", j.entry.c_str(),
                j.max, j.i_nov, j.j_roughness, j.reference_max, j.reference_i_nov,
                j.reference_j_roughness);
    EXPECT_LE(j.max, j.reference_max)
        << j.entry << " at (" << j.i_nov << ", " << j.j_roughness << ")";
  }
}

// A step between neighbouring cells makes the bilinear lookup between them poor: at the midpoints,
// where a lookup averages the two cells' entries, the LTC is judged against the lobe there. Per
// region the mean and the max against ltc_code's table: α ≥ 0.1, and its grazing part (midpoints
// reaching the last row), where the fit used to jump; α < 0.1 by the mean, without the midpoints
// from the first roughness column (α = 1e-5, the next 0.0023), where any table's lookup is off by
// the grid itself.
TEST(LtcCode, LookupsBetweenCellsAreNoWorse) {
  const auto& c = subset_comparison().comparison;
  const auto& g = subset_comparison().table.grid;
  const int n = kSubsetSize;
  struct Region {
    const char* name;
    std::function<bool(int a, int b)> in;
    bool max = true;
    double sum = 0, reference_sum = 0, worst = 0, reference_worst = 0;
    int count = 0;
  };
  std::vector<Region> regions{
      {"alpha >= 0.1", [&](int a, int) { return g.alpha[a / n] >= 0.1; }},
      {"alpha >= 0.1, grazing",
       [&](int a, int b) { return g.alpha[a / n] >= 0.1 && b % n == n - 1; }},
      {"alpha < 0.1", [&](int a, int) { return g.alpha[a / n] < 0.1 && a / n > 0; }, false}};
  for (auto& r : regions) {
    for (size_t k = 0; k < c.midpoint_cells.size(); ++k) {
      if (!r.in(c.midpoint_cells[k].first, c.midpoint_cells[k].second)) continue;
      r.sum += c.midpoint_error[k], r.reference_sum += c.midpoint_reference_error[k], ++r.count;
      r.worst = std::max(r.worst, c.midpoint_error[k]);
      r.reference_worst = std::max(r.reference_worst, c.midpoint_reference_error[k]);
    }
    ASSERT_GT(r.count, 0) << r.name;
    EXPECT_LE(r.sum / r.count, r.reference_sum / r.count) << r.name;
    if (r.max) {
      EXPECT_LE(r.worst, r.reference_worst) << r.name;
    }
  }
}

}  // namespace
}  // namespace fl::analysis
