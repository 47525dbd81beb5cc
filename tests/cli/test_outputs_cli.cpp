// Outputs and options of every command: standard output checked (a full disk exits 1), --out
// never creates missing folders, numbers range-checked, scenes bounded, error lines bounded.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "test_util.h"

namespace fl {
namespace {

using test::cli;
using test::run_command;

int lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

// Every command that writes to standard output, into a full disk: exit status 1 and a line naming
// standard output, never 0.
TEST(OutputsCli, FullDiskOnStandardOutputExitsOne) {
  const std::string scene = std::string(FL_SOURCE_DIR) + "/examples/scene_metals.yaml";
  for (const std::string& args : std::vector<std::string>{
           " --version", " --help", " materials", " -q presets gold", " -q table schlick gold",
           " -q curve gold", " shader schlick", " -q speed gold", " -q plan '" + scene + "'",
           " -q presets --consensus Au", " pages 'main/Au/nk/*'"}) {
    const auto r = run_command("(" + cli() + args + " > /dev/full)");
    EXPECT_EQ(r.status, 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find("standard output: write failed"), std::string::npos) << args << r.err;
  }
}

// One rule for every output: its folder must exist; the message is the same everywhere, given
// before any work, and nothing is created.
TEST(OutputsCli, OutNeverCreatesMissingFolders) {
  test::TempDir tmp;
  const std::string m = tmp.path() + "/typo";
  const std::string scene = std::string(FL_SOURCE_DIR) + "/examples/scene_metals.yaml";
  for (const std::string& args : std::vector<std::string>{
           " lut dfg --size 4 --samples 256 --out " + m + "/x.csv",
           " render gold --out " + m + "/x.exr", " plan '" + scene + "' --out " + m + "/plan",
           " plan '" + scene + "' --plot " + m + "/p.png",
           " library 'main/Au/nk/J*' --out " + m + "/lib",
           " basis 'main/Au/nk/*' --out " + m + "/b", " plot strip gold --out " + m + "/s.png",
           " reproduce --out " + m + "/r", " speed gold --plot " + m + "/s.png",
           " presets gold --out " + m + "/p.csv"}) {
    const auto r = run_command(cli() + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("the folder " + m + " does not exist (outputs never create folders)"),
              std::string::npos)
        << args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(m)) << args;
  }
}

TEST(OutputsCli, NumbersAndNamesAreRangeChecked) {
  test::TempDir tmp;
  const std::string scene = std::string(FL_SOURCE_DIR) + "/examples/scene_metals.yaml";
  const std::string out = " --out " + tmp.path() + "/t.csv";
  const std::pair<std::string, std::string> cases[] = {
      {" lut dfg --size 0" + out, "--size 0 out of range (2 to 4096)"},
      {" lut ltc --size 4 --samples 1" + out, "--samples 1 is below 256"},
      {" lut dfg --size 4 --samples 255" + out, "--samples 255 is below 256"},
      {" --min-coverage nan presets gold", "--min-coverage: 'nan' is not a number from 0 to 1"},
      {" --min-coverage 1.5 presets gold", "--min-coverage: '1.5' is not a number from 0 to 1"},
      {" plan '" + scene + "' --out ''", "--out: is empty"},
      {" --display '' presets gold", "--display: is empty"},
      {" --view '' presets gold", "--view: is empty"},
      {" --space '' presets gold", "--space: is empty"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_command(cli() + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/t.csv"));
  }
}

// A scene's repeated entries are merged (with a note); past the limits a scene is refused in one
// line; a second YAML document is refused rather than dropped.
TEST(OutputsCli, ScenesAreBounded) {
  test::TempDir tmp;
  std::string many = "materials:\n";
  for (int i = 0; i < 1000; ++i) many += "  - gold\n";
  const auto r = run_command(cli() + " plan '" + tmp.file("gold.yaml", many) + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("'gold' listed 1000 times (lines 2, 3, 4, 5, 6, ...): merged into one"),
            std::string::npos)
      << r.err;
  int rows = 0;  // one material row: gold, under the one shader of the scene
  for (size_t p = r.out.find("| Gold |"); p != std::string::npos; p = r.out.find("| Gold |", p + 1))
    ++rows;
  EXPECT_EQ(rows, 2) << r.out;  // the scene's option table and the per-material table

  std::string rough = "materials: [gold]\nroughness: [";
  for (int i = 0; i < 10000; ++i) rough += (i ? ", " : "") + std::to_string(i / 10000.0);
  rough += "]\n";
  const auto r2 = run_command(cli() + " plan '" + tmp.file("rough.yaml", rough) + "'");
  EXPECT_EQ(r2.status, 2);
  EXPECT_NE(r2.err.find(":2: 10000 distinct roughness values, more than the 8 a scene allows"),
            std::string::npos)
      << r2.err;
  EXPECT_EQ(lines(r2.err), 1);

  std::string distinct = "materials:\n";
  for (int i = 0; i < 65; ++i) distinct += "  - m" + std::to_string(i) + ".csv\n";
  const auto r3 = run_command(cli() + " plan '" + tmp.file("distinct.yaml", distinct) + "'");
  EXPECT_EQ(r3.status, 2);
  EXPECT_NE(r3.err.find(":66: 65 distinct materials, more than the 64 a scene allows"),
            std::string::npos)
      << r3.err;

  const auto r4 =
      run_command(cli() + " plan '" +
                  tmp.file("two.yaml", "materials: [gold]\n---\nmaterials: [copper]\n") + "'");
  EXPECT_EQ(r4.status, 2);
  EXPECT_NE(r4.err.find(":2: invalid YAML: a second YAML document ('---'): a file holds one "
                        "document"),
            std::string::npos)
      << r4.err;
}

// A catalog name holding a line break stays on its row of a Markdown table; a 100 KB name is cut
// in the error line.
TEST(OutputsCli, NamesDoNotBreakTablesOrErrorLines) {
  test::TempDir tmp;
  tmp.file("cat/a.yml", "name: \"Gold\\nleaf\"\nclass: metal\nsource: main/Au/nk/Johnson\n");
  const auto r = run_command(std::string("'") + FL_CLI + "' --db '" + FL_DEFAULT_DB +
                             "' --materials '" + tmp.path() + "/cat' materials --format md");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("| Gold leaf |"), std::string::npos) << r.out;
  for (size_t p = 0, e; (e = r.out.find('\n', p)) != std::string::npos; p = e + 1)
    if (e > p && r.out[p] == '|') EXPECT_EQ(r.out[e - 1], '|') << r.out.substr(p, e - p);

  const auto r2 = run_command(cli() + " presets '" + std::string(100000, 'x') + "'");
  EXPECT_EQ(r2.status, 2);
  EXPECT_LT(r2.err.size(), 1200u) << r2.err.size();
  EXPECT_NE(r2.err.find("bytes)"), std::string::npos) << r2.err;
}

}  // namespace
}  // namespace fl
