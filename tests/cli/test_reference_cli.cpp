// `shader --reference` and `plan --out`'s reference.csv through the CLI: the rows a port is tested
// against (their engine values are checked on a Vulkan driver by tests/vulkan/). Here: the points
// listed, Schlick's punctual values against its formula, the truth at roughness 0 (a lobe of
// α = 1e-5) against the spectral curve at n·v, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "csv_reader.h"
#include "test_util.h"

namespace fl {
namespace {

// The reference.csv columns, in order.
const std::vector<std::string> kColumns{
    "material", "model",    "parameters", "lighting", "function", "nov",     "roughness",
    "engine_r", "engine_g", "engine_b",   "truth_r",  "truth_g",  "truth_b", "de00"};
// n·v of every row: the view angles 0, 30, 50, 65, 75, 85° and the grazing edge 0.001.
constexpr int kNovs = 7;
// The printed values: 9 significant digits.
constexpr double kPrinted = 1e-8;
// Truth at roughness 0 (α = 1e-5: the lobe's v·h within about 1e-5 of n·v, the curve tabulated at
// 513 values of cos θ) against the curve at n·v.
constexpr double kMirrorTruth = 2e-4;

std::vector<test::CsvRecord> reference(const std::string& args) {
  const auto r = test::run_command(test::cli() + " shader " + args);
  EXPECT_EQ(r.status, 0) << r.err;
  const auto rows = test::csv_rows(r.out);
  EXPECT_FALSE(rows.empty());
  if (!rows.empty()) EXPECT_EQ(rows[0], kColumns);
  return test::csv_records(r.out);
}

std::map<std::string, double> parameters(const test::CsvRecord& row) {
  std::map<std::string, double> out;
  std::istringstream in(row.at("parameters"));
  for (std::string kv; in >> kv;)
    out[kv.substr(0, kv.find('='))] = std::stod(kv.substr(kv.find('=') + 1));
  return out;
}

// Under punctual lights: the model at cos θ = n·v, Schlick's F0 + (1 − F0)(1 − μ)⁵ per channel.
TEST(ReferenceCli, PunctualSchlickIsItsFormula) {
  const auto rows = reference("schlick --lighting punctual --reference gold glass_bk7");
  ASSERT_EQ(rows.size(), 2u * kNovs);
  for (const auto& r : rows) {
    EXPECT_EQ(r.at("function"), "fresnel_schlick");
    EXPECT_EQ(r.at("roughness"), "");
    const auto p = parameters(r);
    const double mu = std::stod(r.at("nov")), m5 = std::pow(1 - mu, 5);
    int c = 0;
    for (const char* ch : {"r", "g", "b"}) {
      const double f0 = p.at(std::string("f0_") + ch);
      EXPECT_NEAR(std::stod(r.at(std::string("engine_") + ch)), f0 + (1 - f0) * m5, kPrinted)
          << r.at("material") << " n·v " << mu << " channel " << c++;
    }
  }
}

// Under ibl: the roughness values given and the tables' edges 0 and 1, × kNovs; the truth at
// roughness 0 is the spectral curve at n·v (the punctual rows' truth).
TEST(ReferenceCli, IblRowsCoverTheEdgesAndTheMirrorTruthIsTheCurve) {
  const auto ibl = reference("f82 --lighting ibl --reference silver --roughness 0.5 0.25");
  ASSERT_EQ(ibl.size(), 4u * kNovs);
  std::set<std::string> roughness;
  for (const auto& r : ibl) {
    roughness.insert(r.at("roughness"));
    EXPECT_EQ(r.at("function"), "fresnel_f82_ibl");
  }
  EXPECT_EQ(roughness, (std::set<std::string>{"0", "0.25", "0.5", "1"}));
  const auto curve = reference("f82 --lighting punctual --reference silver");
  ASSERT_EQ(curve.size(), static_cast<size_t>(kNovs));
  for (size_t k = 0; k < kNovs; ++k) {
    const auto& lobe = ibl[k];  // roughness 0 comes first
    ASSERT_EQ(lobe.at("roughness"), "0");
    ASSERT_EQ(lobe.at("nov"), curve[k].at("nov"));
    for (const char* ch : {"truth_r", "truth_g", "truth_b"})
      EXPECT_NEAR(std::stod(lobe.at(ch)), std::stod(curve[k].at(ch)), kMirrorTruth)
          << "n·v " << lobe.at("nov") << " " << ch;
  }
}

TEST(ReferenceCli, BadInput) {
  for (const char* args :
       {"f82 --roughness 0.3", "f82 --reference gold --roughness 1.5",
        "f82 --reference no_such_material", "f82 --lighting sun --reference gold"}) {
    const auto r = test::run_command(test::cli() + " shader " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

}  // namespace
}  // namespace fl
