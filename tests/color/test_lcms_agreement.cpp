// Our CIEDE2000 (the differentiable template and the double fast path) against Little CMS's
// cmsCIE2000DeltaE on the 34 pairs of Sharma, Wu & Dalal 2005, and the fast path against the
// template on many pairs. Correctness only; speed is measured in bench/bench_speed.cpp.
#include <gtest/gtest.h>
#include <lcms2.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "color/ciede2000_fast.h"
#include "color/lab.h"

namespace {

using fl::color::Lab;

// Two independent double implementations of the same closed formula agree to rounding.
constexpr double kLcmsAgreement = 1e-9;
// The fast path reorders the same arithmetic (hue vectors instead of angles).
constexpr double kFastPathAgreement = 1e-12;

struct Pair {
  int id;
  Lab a, b;
  double published;
};

std::vector<Pair> sharma_pairs() {
  std::ifstream in(std::string(FL_SHARED_TESTDATA) + "/ciede2000_sharma2005.csv");
  std::vector<Pair> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line.rfind("pair", 0) == 0) continue;
    std::stringstream ss(line);
    std::vector<double> v;
    for (std::string f; std::getline(ss, f, ',');) v.push_back(std::stod(f));
    if (v.size() != 8) continue;
    out.push_back({static_cast<int>(v[0]), {v[1], v[2], v[3]}, {v[4], v[5], v[6]}, v[7]});
  }
  return out;
}

double lcms_de2000(const Lab& a, const Lab& b) {
  const cmsCIELab la{a.L, a.a, a.b}, lb{b.L, b.a, b.b};
  return cmsCIE2000DeltaE(&la, &lb, 1.0, 1.0, 1.0);
}

TEST(LcmsAgreement, ThirtyFourSharmaPairsWithin1em9) {
  const auto pairs = sharma_pairs();
  constexpr size_t kPublishedPairs = 34;
  ASSERT_EQ(pairs.size(), kPublishedPairs);
  double worst_template = 0, worst_fast = 0;
  for (const auto& p : pairs) {
    const double lcms = lcms_de2000(p.a, p.b);
    constexpr double kPublishedDecimals = 1e-4;
    EXPECT_NEAR(lcms, p.published, kPublishedDecimals) << "pair " << p.id;
    const double ours_t = fl::color::ciede2000<double>(p.a, p.b);
    const double ours_f = fl::color::ciede2000_fast(p.a, p.b);
    EXPECT_NEAR(ours_t, lcms, kLcmsAgreement) << "pair " << p.id;
    EXPECT_NEAR(ours_f, lcms, kLcmsAgreement) << "pair " << p.id;
    EXPECT_NEAR(ours_f, ours_t, kFastPathAgreement) << "pair " << p.id;
    // The formula is symmetric.
    EXPECT_NEAR(fl::color::ciede2000_fast(p.b, p.a), lcms, kLcmsAgreement) << "pair " << p.id << " swapped";
    worst_template = std::max(worst_template, std::abs(ours_t - lcms));
    worst_fast = std::max(worst_fast, std::abs(ours_f - lcms));
  }
  RecordProperty("worst_template_vs_lcms", std::to_string(worst_template));
  RecordProperty("worst_fast_vs_lcms", std::to_string(worst_fast));
}

TEST(LcmsAgreement, FastPathMatchesTemplateOnRandomPairs) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> L(0.0, 100.0), ab(-120.0, 120.0), d(-2.0, 2.0), tiny(-1e-6, 1e-6);
  constexpr int kPairs = 200000;
  for (int i = 0; i < kPairs; ++i) {
    const Lab x{L(rng), ab(rng), ab(rng)};
    Lab y;
    switch (i % 4) {
      case 0: y = {L(rng), ab(rng), ab(rng)}; break;               // anywhere
      case 1: y = {x.L + d(rng), x.a + d(rng), x.b + d(rng)}; break;  // near
      case 2: y = {x.L + tiny(rng), x.a + tiny(rng), x.b + tiny(rng)}; break;  // almost equal
      default: y = {L(rng), -x.a + d(rng), -x.b + d(rng)}; break;  // near-opposite hues
    }
    const double t = fl::color::ciede2000<double>(x, y);
    const double f = fl::color::ciede2000_fast(x, y);
    ASSERT_NEAR(f, t, kFastPathAgreement) << "L,a,b " << x.L << "," << x.a << "," << x.b << " / " << y.L << ","
                                          << y.a << "," << y.b;
  }
}

TEST(LcmsAgreement, FastPathNeutralAndIdenticalColours) {
  const Lab grey{50, 0, 0}, grey2{60, 0, 0}, red{50, 60, 10};
  EXPECT_EQ(fl::color::ciede2000_fast(red, red), 0.0);
  EXPECT_NEAR(fl::color::ciede2000_fast(grey, grey2), fl::color::ciede2000<double>(grey, grey2), kFastPathAgreement);
  EXPECT_NEAR(fl::color::ciede2000_fast(grey, red), lcms_de2000(grey, red), kLcmsAgreement);
}

}  // namespace
