// The `lut` command and `table lut-accuracy` through the CLI: files, determinism, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "report/exr.h"
#include "test_util.h"

namespace fl {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(LutCli, WritesTablesDeterministically) {
  test::TempDir tmp;
  const std::string lut = std::string("'") + FL_CLI + "' -q lut ";
  auto r = test::run_command(lut + "dfg --size 4 --samples 256 --out '" + tmp.path() + "/a.csv'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto csv = slurp(tmp.path() + "/a.csv");
  // Three comment lines (axes, channels, shader formula), the header, 16 rows.
  const auto header = csv.find("\nnov,");
  ASSERT_NE(header, std::string::npos);
  EXPECT_EQ(csv.substr(header + 1, csv.find('\n', header + 1) - header - 1), "nov,perceptual_roughness,alpha,dfg1,dfg2,dfg_f82");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 20);
  r = test::run_command(lut + "dfg --size 4 --samples 256 --threads 1 --out '" + tmp.path() + "/b.csv'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(tmp.path() + "/b.csv"), csv);

  r = test::run_command(lut + "dfg --size 4 --samples 256 --out '" + tmp.path() + "/dfg.h'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(tmp.path() + "/dfg.h").find("constexpr float kDfgLut[4 * 4 * 3]"), std::string::npos);
  r = test::run_command(lut + "dfg --layout filament --size 4 --samples 256 --out '" + tmp.path() + "/f.h'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(tmp.path() + "/f.h").find("constexpr std::uint16_t kDfgLut[4 * 4 * 3]"), std::string::npos);

  r = test::run_command(lut + "ltc-moments --size 4 --samples 256 --out '" + tmp.path() + "/m.csv'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto m = slurp(tmp.path() + "/m.csv");
  EXPECT_EQ(m.substr(0, m.find('\n')), "nov,perceptual_roughness,alpha,n_d,f_d,l_d");

  r = test::run_command(lut + "ltc --size 4 --samples 256 --out '" + tmp.path() + "/ltc.exr'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto t1 = report::read_exr(tmp.path() + "/ltc_1.exr");
  const auto t2 = report::read_exr(tmp.path() + "/ltc_2.exr");
  EXPECT_EQ(t1.width, 4);
  EXPECT_EQ(t1.channels.size(), 4u);
  EXPECT_EQ(t2.channels.size(), 4u);
  EXPECT_TRUE(std::filesystem::exists(tmp.path() + "/ltc.csv"));
}

TEST(LutCli, BadInputExitsTwoAndWritesNothing) {
  test::TempDir tmp;
  const std::string lut = std::string("'") + FL_CLI + "' lut ";
  for (const std::string args : {"dfg --size 1 --out x.csv", "dfg --size 4 --out x.txt", "ltc-moments --size 4 --out x.h",
                                 "dfg --size 4 --out x.inc", "dfg --layout unreal --size 4 --out x.csv",
                                 "ltc --size 4 --samples 0 --out x.exr", "dfg --size 4", "frob --out x.csv"}) {
    const auto r = test::run_command("cd '" + tmp.path() + "' && " + lut + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_TRUE(std::filesystem::is_empty(tmp.path()));
  for (const char* sub : {"", "dfg", "ltc-moments", "ltc"}) {
    const auto r = test::run_command(lut + sub + " --help");
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.out.find(std::string(sub).empty() ? "ltc-moments" : "--out"), std::string::npos) << sub;
  }
}

TEST(LutCli, F82MomentBeatsSchlickOnMetals) {
  const auto r = test::run_command(test::cli() + " -q table lut-accuracy");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "material,schlick_median_de00,schlick_max_de00,f82_median_de00,f82_max_de00");
  std::vector<double> schlick, f82;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(row, cell, ',')) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 5u) << line;
    schlick.push_back(std::stod(cells[1]));
    f82.push_back(std::stod(cells[3]));
  }
  ASSERT_EQ(schlick.size(), 14u);  // the catalog's metals
  std::sort(schlick.begin(), schlick.end());
  std::sort(f82.begin(), f82.end());
  EXPECT_LT(f82[7] + f82[6], schlick[7] + schlick[6]);  // medians of 14 values
}

}  // namespace
}  // namespace fl
