// The same bits on every x86-64 CPU: each computation whose result could depend on the processor
// is run here on every path this CPU can take, on the same inputs, against the baseline path.
// - The basis's stacked QR, under the cache sizes of several CPUs (Eigen sizes the blocks of its
//   matrix products from the caches it reads with cpuid): bit for bit.
// - The batched CIEDE2000 and the fits' residuals on every Highway instruction set this CPU has,
//   against the baseline set (SSE2-class EMU128 or SSSE3): within kHighwayPaths, since Highway's
//   polynomial atan, exp, log and sin fuse multiply-adds where the instruction set has them.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/basis/basis.h"
#include "color/ciede2000_batch.h"
#include "fresnel/exact.h"

namespace fl {
namespace {

// Highway's paths differ only in fused against separate multiply-adds inside its polynomial
// approximations (about 1 ulp each, a few dozen on the way to a ΔE of order 1).
constexpr double kHighwayPaths = 1e-12;

// The caches of CPUs this runs on: an Intel Xeon (48 KiB L1d, 2 MiB L2, 480 MiB L3), an AMD EPYC
// Zen 4 (32 KiB, 1 MiB, 32 MiB), and Eigen's defaults when it cannot read them.
struct Caches {
  std::ptrdiff_t l1, l2, l3;
};
constexpr Caches kCaches[] = {{48 << 10, 2 << 20, 480 << 20},
                              {32 << 10, 1 << 20, 32 << 20},
                              {16 << 10, 512 << 10, 512 << 10},
                              {64 << 10, 4 << 20, 16 << 20}};

// 32 pages' worth of conductor curves at 48 wavelengths (the construction's block), from a spread
// of complex indices: a stack of 1,536 rows over 91 samples, wide enough for blocked products.
analysis::CurveRows conductor_rows(const std::vector<double>& mu) {
  analysis::CurveRows rows;
  rows.samples = static_cast<int>(mu.size());
  for (int page = 0; page < 32; ++page)
    for (int l = 0; l < 48; ++l) {
      const std::complex<double> eta(0.2 + 0.09 * page + 0.01 * l, 1.0 + 0.12 * page - 0.02 * l);
      for (double m : mu) rows.values.push_back(fresnel::fresnel_conductor(m, eta));
      rows.weights.push_back(1.0 / 48 + 1e-3 * std::sin(0.7 * l));
    }
  return rows;
}

analysis::ResidualSvd basis_svd_with_caches(const Caches& c) {
  const std::ptrdiff_t l1 = Eigen::l1CacheSize(), l2 = Eigen::l2CacheSize(),
                       l3 = Eigen::l3CacheSize();
  Eigen::setCpuCacheSizes(c.l1, c.l2, c.l3);
  const auto mu = analysis::basis_mu_samples(91);
  analysis::ResidualStack stack(mu), merged(mu);
  stack.add(conductor_rows(mu));
  merged.merge(stack);
  auto svd = merged.solve(3);
  Eigen::setCpuCacheSizes(l1, l2, l3);
  return svd;
}

TEST(CpuPaths, BasisStackGivesTheSameBitsWhateverTheCaches) {
  const auto baseline = basis_svd_with_caches(kCaches[0]);
  for (const auto& c : kCaches) {
    const auto svd = basis_svd_with_caches(c);
    ASSERT_EQ(svd.singular_values.size(), baseline.singular_values.size());
    for (size_t k = 0; k < svd.singular_values.size(); ++k)
      EXPECT_EQ(svd.singular_values[k], baseline.singular_values[k]) << "L1 " << c.l1 << " σ" << k;
    for (size_t k = 0; k < svd.functions.size(); ++k)
      EXPECT_EQ(svd.functions[k], baseline.functions[k]) << "L1 " << c.l1 << " b" << k + 2;
  }
}

// Lab pairs spread over the gamut, hues all round, near-neutral and opposite-hue pairs included.
void lab_pairs(std::vector<color::Lab>& a, std::vector<color::Lab>& b) {
  for (int i = 0; i < 4099; ++i) {
    const double h = 0.37 * i, c = 60.0 * std::abs(std::sin(0.11 * i));
    a.push_back({5.0 + 90.0 * std::abs(std::sin(0.013 * i)), c * std::cos(h), c * std::sin(h)});
    const double dh = i % 5 == 0 ? 3.14159 : 0.2 * std::sin(0.3 * i);
    const double c2 = i % 7 == 0 ? 0.0 : c * (1.0 + 0.1 * std::cos(0.5 * i));
    b.push_back(
        {a.back().L + 3.0 * std::sin(0.7 * i), c2 * std::cos(h + dh), c2 * std::sin(h + dh)});
  }
}

bool fuses_multiply_adds(const std::string& target) {
  return target == "AVX2" || target == "AVX3";
}

// Against the baseline (the last, narrowest set) within kHighwayPaths; the sets that fuse
// multiply-adds, every CPU made since 2013, bit for bit against each other.
TEST(CpuPaths, BatchedCiede2000OnEveryInstructionSetAgreesWithTheBaseline) {
  std::vector<color::Lab> a, b;
  lab_pairs(a, b);
  const auto targets = color::ciede2000_batch_targets();
  ASSERT_FALSE(targets.empty());
  std::vector<double> base(a.size()), out(a.size()), fused;
  color::ciede2000_batch_on(targets.back(), a, b, base);
  for (const auto& target : targets) {
    color::ciede2000_batch_on(target, a, b, out);
    if (fuses_multiply_adds(target)) {
      if (fused.empty()) fused = out;
      EXPECT_EQ(out, fused) << target;
    }
    double worst = 0;
    int differ = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      worst = std::max(worst, std::abs(out[i] - base[i]));
      differ += out[i] != base[i];
    }
    EXPECT_LE(worst, kHighwayPaths) << target << " against " << targets.back();
    std::ostringstream note;
    note << worst << " (" << differ << " of " << a.size() << " differ)";
    RecordProperty("worst_" + target + "_vs_" + targets.back(), note.str());
  }
}

}  // namespace
}  // namespace fl
