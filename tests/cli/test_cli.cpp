// The command-line contract: exit statuses, messages, atomic output, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "test_util.h"

namespace fl {
namespace {

using test::cli;
using test::run_command;

// The subcommands a help page lists: the first word of each line of its "Subcommands:" section.
std::vector<std::string> listed_subcommands(const std::string& help) {
  std::vector<std::string> out;
  const auto at = help.find("\nSubcommands:\n");
  if (at == std::string::npos) return out;
  std::istringstream in(help.substr(at + 14));
  for (std::string line; std::getline(in, line) && !line.empty();) {
    if (line.rfind("  ", 0) != 0 || line[2] == ' ') continue;  // a wrapped description
    out.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return out;
}

// Every command the CLI registers, found from the help pages themselves (the top level's and, for
// commands with their own subcommands, theirs): each prints its usage and exits 0.
std::vector<std::string> registered_commands() {
  std::vector<std::string> pending{""}, visited;
  while (!pending.empty()) {
    const std::string cmd = pending.back();
    pending.pop_back();
    const auto r = run_command(cli() + " " + cmd + " --help");
    EXPECT_EQ(r.status, 0) << cmd;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << cmd;
    visited.push_back(cmd);
    for (const auto& sub : listed_subcommands(r.out))
      pending.push_back(cmd.empty() ? sub : cmd + " " + sub);
  }
  return visited;
}

TEST(Cli, HelpForEveryCommand) {
  const auto visited = registered_commands();
  // The README's tour, by name: each is registered (and so was visited above).
  for (const char* cmd : {"materials",  "curve",       "presets",         "table",   "reproduce",
                          "lut",        "lut dfg",     "lut ltc-moments", "lut ltc", "plot",
                          "plot strip", "plot curves", "render",          "speed",   "plan",
                          "pages",      "library",     "consensus",       "shader",  "basis"})
    EXPECT_NE(std::find(visited.begin(), visited.end(), cmd), visited.end()) << cmd;
}

// The README tours every command with an example: a line `fresnel-lab COMMAND ...` for every
// command without subcommands of its own (`lut dfg`, not `lut`).
TEST(Cli, ReadmeHasAnExampleOfEveryCommand) {
  std::ifstream in(std::string(FL_SOURCE_DIR) + "/README.md");
  const std::string readme{std::istreambuf_iterator<char>(in), {}};
  ASSERT_FALSE(readme.empty());
  const auto visited = registered_commands();
  for (const auto& cmd : visited) {
    if (cmd.empty()) continue;
    const bool parent = std::any_of(visited.begin(), visited.end(), [&](const std::string& c) {
      return c.rfind(cmd + " ", 0) == 0;
    });
    if (!parent)
      EXPECT_NE(readme.find("fresnel-lab " + cmd + " "), std::string::npos)
          << "README.md has no example of '" << cmd << "'";
  }
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_command(cli()).status, 2);
  EXPECT_EQ(run_command(cli() + " frobnicate").status, 2);
  EXPECT_EQ(run_command(cli() + " table nosuchtable").status, 2);
  EXPECT_EQ(run_command(cli() + " --space srgb_gamma table schlick").status, 2);
  EXPECT_EQ(run_command(cli() + " --illuminant F99 table schlick").status, 2);
  EXPECT_EQ(run_command(cli() + " curve unobtainium").status, 2);
  EXPECT_EQ(run_command(cli() + " --angles 2 table schlick").status, 2);
  EXPECT_EQ(run_command(cli() + " --step-nm 0 table schlick").status, 2);
  EXPECT_EQ(run_command(cli() + " --step-nm nan table schlick").status, 2);
  EXPECT_EQ(run_command(cli() + " table blend --blend-weight 2").status, 2);
  const auto unknown = run_command(cli() + " frobnicate");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("unknown command 'frobnicate'"), std::string::npos) << unknown.err;
  EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1) << unknown.err;
}

TEST(Cli, ExtremeOpticalConstantsAreRejectedNotCrashed) {
  test::TempDir tmp;
  for (const char* row : {"300,1,1e80\n900,1,2\n", "300,1e80,1\n900,1,2\n"}) {
    const auto f = tmp.file("huge.csv", std::string("lambda_nm,n,k\n") + row);
    const auto r = run_command(cli() + " curve '" + f + "' --params fitted");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("not physical"), std::string::npos) << r.err;
  }
}

TEST(Cli, MalformedInputNamesFileAndLineAndLeavesNoOutput) {
  test::TempDir tmp;
  const auto bad = tmp.file(
      "bad.yml",
      "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 1.0 2.0\n        0.5 oops 2.0\n");
  const auto r = run_command(cli() + " curve '" + bad + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(bad + ":5:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'oops' is not a finite number"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty());

  // A catalog with a broken entry: reproduce fails and writes nothing.
  const auto cat = tmp.path() + "/catalog";
  tmp.file("catalog/good.yml", "name: Good\nclass: dielectric\nconstant: {n: 1.5}\n");
  tmp.file("catalog/broken.yml", "name: Broken\nclass: metal\nsource: \"main/Au/nk/NoSuchPage\"\n");
  const auto out = tmp.path() + "/out";
  const auto r2 = run_command("'" + std::string(FL_CLI) + "' --db '" + FL_DEFAULT_DB +
                              "' --materials '" + cat + "' reproduce --out '" + out + "'");
  EXPECT_EQ(r2.status, 2);
  EXPECT_NE(r2.err.find("NoSuchPage.yml: no such file"), std::string::npos) << r2.err;
  EXPECT_FALSE(std::filesystem::exists(out) && !std::filesystem::is_empty(out));
}

TEST(Cli, SchlickTableHasSpecColumns) {
  const auto r = run_command(cli() + " -q table schlick");
  ASSERT_EQ(r.status, 0) << r.err;
  // The stable columns first; the coverage columns are appended after them.
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')),
            "material,class,source,rms_de00,mean_de00,max_de00,coverage,coverage_n,coverage_k,"
            "extrapolated");
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 29);
}

TEST(Cli, CurveAcceptsCatalogNamesDatabasePagesAndFiles) {
  test::TempDir tmp;
  const auto csv = tmp.file("m.csv", "\xEF\xBB\xBFlambda_nm,n,k\r\n300,0.2,3.0\r\n900,0.3,6.0\r\n");
  for (const std::string& m : std::vector<std::string>{"gold", "main/Au/nk/Johnson", csv}) {
    const auto r = run_command(cli() + " -q curve '" + m + "'");
    ASSERT_EQ(r.status, 0) << m << ": " << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 92) << m;  // header + 91 angles
  }
}

TEST(Cli, ReproduceIsDeterministic) {
  test::TempDir tmp;
  const auto a = tmp.path() + "/a", b = tmp.path() + "/b";
  ASSERT_EQ(run_command(cli() + " -q reproduce --out '" + a + "'").status, 0);
  ASSERT_EQ(run_command(cli() + " -q reproduce --out '" + b + "'").status, 0);
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(a)) {
    if (e.is_directory()) continue;  // figures/: its files are compared one by one
    auto slurp = [](const std::filesystem::path& p) {
      std::ifstream in(p, std::ios::binary);
      return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(slurp(e.path()),
              slurp(std::filesystem::path(b) / std::filesystem::relative(e.path(), a)))
        << e.path();
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << "temporary file left behind";
    ++files;
  }
  EXPECT_GE(files, 3);
  EXPECT_TRUE(std::filesystem::exists(a + "/schlick.csv"));
  EXPECT_TRUE(std::filesystem::exists(a + "/README.md"));
}

}  // namespace
}  // namespace fl
