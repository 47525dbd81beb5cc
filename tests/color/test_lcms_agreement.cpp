// Our CIEDE2000 (the differentiable template and the batched SIMD kernel) against Little CMS's
// cmsCIE2000DeltaE on the 34 pairs of Sharma, Wu & Dalal 2005, and the batched kernel against the
// template (and Little CMS) on many pairs. Correctness
// only; speed is measured in bench/bench_speed.cpp.
#include <gtest/gtest.h>
#include <lcms2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "color/ciede2000_batch.h"
#include "color/lab.h"
#include "csv_reader.h"

namespace {

using fl::color::Lab;

// Two independent double implementations of the same closed formula agree to rounding.
constexpr double kLcmsAgreement = 1e-9;
// The batched kernel reorders the template's arithmetic (hue vectors instead of angles) in SIMD
// lanes, with Highway's atan, exp and sin
// (3 ULP or better) for libm's and fused multiply-adds where the instruction set has them.
constexpr double kBatchAgreement = 1e-12;

struct Pair {
  int id;
  Lab a, b;
  double published;
};

std::vector<Pair> sharma_pairs() {
  std::vector<Pair> out;
  for (const auto& row :
       fl::test::csv_file_rows(std::string(FL_SHARED_TESTDATA) + "/ciede2000_sharma2005.csv",
                               {.skip_comments = true})) {
    if (row[0] == "pair") continue;  // the header
    const auto v = fl::test::csv_numbers(row);
    if (v.size() != 8) continue;
    out.push_back({static_cast<int>(v[0]), {v[1], v[2], v[3]}, {v[4], v[5], v[6]}, v[7]});
  }
  return out;
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

double lcms_de2000(const Lab& a, const Lab& b) {
  const cmsCIELab la{a.L, a.a, a.b}, lb{b.L, b.a, b.b};
  return cmsCIE2000DeltaE(&la, &lb, 1.0, 1.0, 1.0);
}

TEST(LcmsAgreement, ThirtyFourSharmaPairsWithin1em9) {
  const auto pairs = sharma_pairs();
  constexpr size_t kPublishedPairs = 34;
  ASSERT_EQ(pairs.size(), kPublishedPairs);
  double worst_template = 0;
  for (const auto& p : pairs) {
    const double lcms = lcms_de2000(p.a, p.b);
    constexpr double kPublishedDecimals = 1e-4;
    EXPECT_NEAR(lcms, p.published, kPublishedDecimals) << "pair " << p.id;
    const double ours_t = fl::color::ciede2000<double>(p.a, p.b);
    EXPECT_NEAR(ours_t, lcms, kLcmsAgreement) << "pair " << p.id;
    // The formula is symmetric.
    EXPECT_NEAR(fl::color::ciede2000<double>(p.b, p.a), lcms, kLcmsAgreement)
        << "pair " << p.id << " swapped";
    worst_template = std::max(worst_template, std::abs(ours_t - lcms));
  }
  RecordProperty("worst_template_vs_lcms", sci(worst_template));
}

}  // namespace

namespace {

// Pairs across CIELAB: anywhere, near, almost equal, near-opposite hues, and some neutral or
// identical colours (the lanes the batched kernel hands to the reference).
void random_pairs(size_t n, uint64_t seed, std::vector<Lab>& a, std::vector<Lab>& b) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> L(0.0, 100.0), ab(-120.0, 120.0), d(-2.0, 2.0),
      tiny(-1e-6, 1e-6);
  a.clear();
  b.clear();
  for (size_t i = 0; i < n; ++i) {
    const Lab x{L(rng), ab(rng), ab(rng)};
    Lab y;
    switch (i % 5) {
      case 0:
        y = {L(rng), ab(rng), ab(rng)};
        break;
      case 1:
        y = {x.L + d(rng), x.a + d(rng), x.b + d(rng)};
        break;
      case 2:
        y = {x.L + tiny(rng), x.a + tiny(rng), x.b + tiny(rng)};
        break;
      case 3:
        y = {L(rng), -x.a + d(rng), -x.b + d(rng)};
        break;
      default:
        y = i % 3 ? Lab{L(rng), 0.0, 0.0} : x;
        break;
    }
    a.push_back(x);
    b.push_back(y);
  }
}

std::vector<double> batch_on(const std::string& target, const std::vector<Lab>& a,
                             const std::vector<Lab>& b) {
  std::vector<double> out(a.size());
  fl::color::ciede2000_batch_on(target, a, b, out);
  return out;
}

TEST(LcmsAgreement, BatchOnSharmaPairsWithin1em9OfLcmsOnEveryInstructionSet) {
  const auto pairs = sharma_pairs();
  ASSERT_EQ(pairs.size(), 34u);
  std::vector<Lab> a, b;
  for (const auto& p : pairs) {
    a.push_back(p.a);
    b.push_back(p.b);
  }
  const auto targets = fl::color::ciede2000_batch_targets();
  ASSERT_FALSE(targets.empty());
  for (const auto& target : targets) {
    const auto de = batch_on(target, a, b), swapped = batch_on(target, b, a);
    double worst = 0;
    for (size_t i = 0; i < pairs.size(); ++i) {
      const double lcms = lcms_de2000(a[i], b[i]);
      EXPECT_NEAR(de[i], lcms, kLcmsAgreement) << target << " pair " << pairs[i].id;
      EXPECT_NEAR(swapped[i], lcms, kLcmsAgreement)
          << target << " pair " << pairs[i].id << " swapped";
      EXPECT_NEAR(de[i], fl::color::ciede2000<double>(a[i], b[i]), kBatchAgreement)
          << target << " pair " << pairs[i].id;
      worst = std::max(worst, std::abs(de[i] - lcms));
    }
    RecordProperty("worst_batch_vs_lcms_" + target, sci(worst));
  }
}

TEST(LcmsAgreement, BatchMatchesTemplateAndLcmsOnRandomPairsOnEveryInstructionSet) {
  // Not a multiple of any vector length: the padded tail is exercised too.
  constexpr size_t kPairs = 20003;
  std::vector<Lab> a, b;
  random_pairs(kPairs, 11, a, b);
  for (const auto& target : fl::color::ciede2000_batch_targets()) {
    const auto de = batch_on(target, a, b);
    double worst_template = 0, worst_lcms = 0;
    for (size_t i = 0; i < kPairs; ++i) {
      const double t = fl::color::ciede2000<double>(a[i], b[i]), l = lcms_de2000(a[i], b[i]);
      ASSERT_NEAR(de[i], t, kBatchAgreement)
          << target << " L,a,b " << a[i].L << "," << a[i].a << "," << a[i].b << " / " << b[i].L
          << "," << b[i].a << "," << b[i].b;
      ASSERT_NEAR(de[i], l, kLcmsAgreement) << target << " pair " << i;
      worst_template = std::max(worst_template, std::abs(de[i] - t));
      worst_lcms = std::max(worst_lcms, std::abs(de[i] - l));
    }
    RecordProperty("worst_batch_vs_template_" + target, sci(worst_template));
    RecordProperty("worst_batch_vs_lcms_" + target, sci(worst_lcms));
  }
}

TEST(LcmsAgreement, BatchShortSpansNeutralAndIdenticalColours) {
  const Lab grey{50, 0, 0}, grey2{60, 0, 0}, red{50, 60, 10}, blue{30, 10, -60};
  // Chromas whose product underflows.
  const Lab faint{50, 1e-160, 2e-160}, faint2{60, -1e-160, 1e-160};
  const std::vector<Lab> a{red, grey, grey, blue, red, faint},
      b{red, grey2, red, red, blue, faint2};
  for (size_t n = 0; n <= a.size(); ++n) {
    std::vector<double> out(n, -1.0);
    fl::color::ciede2000_batch(std::span(a).first(n), std::span(b).first(n), out);
    for (size_t i = 0; i < n; ++i)
      EXPECT_NEAR(out[i], lcms_de2000(a[i], b[i]), kLcmsAgreement) << n << " " << i;
  }
  std::vector<double> wrong(2);
  EXPECT_THROW(fl::color::ciede2000_batch(a, b, wrong), std::invalid_argument);
  EXPECT_THROW(fl::color::ciede2000_batch_on("no such instruction set", a, b, wrong),
               std::invalid_argument);
}

}  // namespace
