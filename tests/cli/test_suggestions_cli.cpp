// What a daily user meets at the command line: subcommands and values suggested as git and cargo
// do, enumerations in any case, a YAML tab named as such, errors pointing at the subcommand's own
// help, which lists the global options, and labelled progress that never restarts.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include "test_util.h"

namespace fl {
namespace {

using test::cli;
using test::run_command;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Expected {
  std::string args;
  std::vector<std::string> in_error;
};

// Each is refused with exit 2, one line on stderr naming the nearest choice (or the choices) and
// the help of the command it belongs to, nothing on stdout.
TEST(Suggestions, SubcommandsAndValues) {
  const std::vector<Expected> cases = {
      {"lut dgf --out x.exr",
       {"unknown lut command 'dgf': did you mean 'dfg'?", "see fresnel-lab lut --help"}},
      {"plot bars gold --out x.png",
       {"unknown plot command 'bars' (expected strip or curves)", "see fresnel-lab plot --help"}},
      {"preset gold", {"unknown command 'preset': did you mean 'presets'?"}},
      {"presets main/AU/nk/Johnson", {"did you mean 'main/Au/nk/Johnson'?"}},
      {"presets glass",
       {"did you mean one of 'glass_bk7', 'glass_f5', 'glass_sf11', 'glass_sf66'?"}},
      {"presets gold --format mtlx --shader openpbs", {"did you mean 'open_pbr_surface'?"}},
      {"shader schlick --lighting IBM", {"did you mean 'ibl'?"}},
      {"shader schlick --lang hsl", {"did you mean 'hlsl'?"}},
      {"render gold --compare all --flip gift --out x.exr", {"did you mean 'gif'?"}},
      {"presets gold --bogus", {"see fresnel-lab presets --help"}},
      {"lut dfg --out x.exr --samples many", {"see fresnel-lab lut dfg --help"}},
  };
  for (const auto& c : cases) {
    const auto r = run_command(cli() + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
    for (const auto& s : c.in_error)
      EXPECT_NE(r.err.find(s), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.out, "") << c.args;
  }
}

// Enumerations and MaterialX's short names are accepted in any case, meaning the canonical value.
TEST(Suggestions, EnumerationsInAnyCase) {
  const auto canonical = run_command(cli() + " -q shader schlick --lighting ibl --lang hlsl");
  const auto upper = run_command(cli() + " -q shader schlick --lighting IBL --lang HLSL");
  ASSERT_EQ(canonical.status, 0) << canonical.err;
  ASSERT_EQ(upper.status, 0) << upper.err;
  EXPECT_EQ(upper.out, canonical.out);
  const auto node = run_command(cli() + " -q presets gold --format mtlx --shader open_pbr_surface");
  const auto shortname = run_command(cli() + " -q presets gold --format mtlx --shader OpenPBR");
  ASSERT_EQ(node.status, 0) << node.err;
  ASSERT_EQ(shortname.status, 0) << shortname.err;
  EXPECT_EQ(shortname.out, node.out);
  test::TempDir tmp;
  const std::string lut = " lut dfg --size 8 --samples 256 --out '" + tmp.path();
  ASSERT_EQ(run_command(cli() + " -q" + lut + "/a.inc' --layout filament").status, 0);
  const auto f = run_command(cli() + " -q" + lut + "/b.inc' --layout Filament");
  ASSERT_EQ(f.status, 0) << f.err;
  EXPECT_EQ(slurp(tmp.path() + "/b.inc"), slurp(tmp.path() + "/a.inc"));
}

// A tab in a YAML file is named, with its line and column, instead of libyaml's "found character
// that cannot start any token".
TEST(Suggestions, YamlTabIsNamed) {
  test::TempDir tmp;
  const auto scene = tmp.file("scene.yaml", "materials:\n\t- gold\n");
  const auto r = run_command(cli() + " plan '" + scene + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("scene.yaml:2: "), std::string::npos) << r.err;  // file and line
  EXPECT_NE(r.err.find("a tab at column 1: YAML indents with spaces, not tabs"), std::string::npos)
      << r.err;
}

// A subcommand's help lists the global options; library's help says names and files work.
TEST(Suggestions, SubcommandHelp) {
  const auto lut = run_command(cli() + " lut dfg --help");
  ASSERT_EQ(lut.status, 0);
  for (const char* s : {"--layout", "Global options", "--space", "--illuminant", "--quiet"})
    EXPECT_NE(lut.out.find(s), std::string::npos) << s << "\n" << lut.out;
  const auto library = run_command(cli() + " library --help");
  ASSERT_EQ(library.status, 0);
  for (const char* s : {"catalog names (gold)", "files", "main/Au/nk/Johnson"})
    EXPECT_NE(library.out.find(s), std::string::npos) << s << "\n" << library.out;
}

// Filament's layout integrates two tables; its progress is one labelled bar that never goes back
// (the second table does not restart at 0 %), ending at 100 % once.
TEST(Suggestions, FilamentProgressNeverRestarts) {
  test::TempDir tmp;
  const auto r = run_command(cli() + " lut dfg --layout filament --size 16 --samples 256 --out '" +
                             tmp.path() + "/d.inc'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::regex line(R"(lut dfg: +(\d+)%)");
  std::vector<int> pct;
  for (auto it = std::sregex_iterator(r.err.begin(), r.err.end(), line);
       it != std::sregex_iterator(); ++it)
    pct.push_back(std::stoi((*it)[1]));
  ASSERT_GE(pct.size(), 5u) << r.err;
  EXPECT_TRUE(std::is_sorted(pct.begin(), pct.end())) << r.err;
  EXPECT_EQ(std::count(pct.begin(), pct.end(), 100), 1) << r.err;
}

}  // namespace
}  // namespace fl
