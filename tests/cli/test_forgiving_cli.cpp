// The command line forgives what people type: global options after the command, names in any case
// and their usual aliases, "did you mean" for near misses, options a format ignores refused, and
// presets written to a file atomically.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "test_util.h"
#include "util/suggest.h"

namespace fl {
namespace {

using test::cli;
using test::run_command;

int lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

// Global options written after the command mean what they mean before it.
TEST(ForgivingCli, GlobalOptionsAfterTheCommand) {
  const auto before = run_command(cli() + " -q --space lin_rec709 presets gold --format gltf");
  const auto after = run_command(cli() + " presets gold --format gltf --space lin_rec709 -q");
  ASSERT_EQ(before.status, 0) << before.err;
  ASSERT_EQ(after.status, 0) << after.err;
  EXPECT_EQ(after.out, before.out);
  EXPECT_EQ(after.err, "");  // -q after the command silences progress too
}

// Aliases and case: the same preset as the canonical spelling, byte for byte.
TEST(ForgivingCli, AliasesAndCaseGiveTheCanonicalResult) {
  const auto canonical = run_command(cli() + " -q --space lin_rec709 presets aluminum chromium");
  ASSERT_EQ(canonical.status, 0) << canonical.err;
  const auto aliased = run_command(cli() + " -q --space LIN_SRGB presets Aluminium chrome");
  ASSERT_EQ(aliased.status, 0) << aliased.err;
  EXPECT_EQ(aliased.out, canonical.out);
  const auto model = run_command(cli() + " -q curve gold --model Generalised-Schlick");
  EXPECT_EQ(model.status, 0) << model.err;
  const auto ocio_name = run_command(cli() + " -q --space 'ACES - ACEScg' presets Au");
  const auto acescg = run_command(cli() + " -q --space acescg presets gold");
  ASSERT_EQ(ocio_name.status, 0) << ocio_name.err;
  EXPECT_EQ(ocio_name.out, acescg.out);
}

struct Misspelling {
  std::string args, suggestion;
};

// Ten misspellings people make; each is one line, exit 2, naming the intended choice.
TEST(ForgivingCli, DidYouMeanForNearMisses) {
  const std::vector<Misspelling> cases = {
      {"presets gld", "did you mean 'gold'?"},
      {"presets alumnium", "did you mean 'aluminum'?"},
      {"presets chromum", "did you mean 'chromium'?"},
      {"presets main/Au/nk/Johnston", "did you mean 'main/Au/nk/Johnson'?"},
      {"presets main/Au/Johnson", "did you mean 'main/Au/nk/Johnson'?"},
      {"presets gold --format gtlf", "did you mean 'gltf'?"},
      {"curve gold --model Shlick", "did you mean 'schlick'?"},
      {"--space acesCGG presets gold", "did you mean 'acescg'?"},
      {"--space lin_rec202 presets gold", "did you mean 'lin_rec2020'?"},
      {"table schlik", "did you mean 'schlick'?"},
  };
  for (const auto& c : cases) {
    const auto r = run_command(cli() + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_EQ(lines(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.suggestion), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.out, "") << c.args;
  }
}

// Options the chosen format would ignore are refused before any work.
TEST(ForgivingCli, OptionsAFormatIgnoresAreRefused) {
  const auto openpbr = run_command(cli() + " presets gold --format gltf --openpbr");
  EXPECT_EQ(openpbr.status, 2);
  EXPECT_NE(openpbr.err.find("--openpbr does not apply to --format gltf"), std::string::npos)
      << openpbr.err;
  const auto shader = run_command(cli() + " presets gold --format csv --shader standard_surface");
  EXPECT_EQ(shader.status, 2);
  EXPECT_NE(shader.err.find("--shader applies to --format mtlx only"), std::string::npos)
      << shader.err;
}

// presets --out writes the same text as standard output, to a file, and never into a folder a
// typo named.
TEST(ForgivingCli, PresetsOutIsTheStandardOutputInAFile) {
  test::TempDir tmp;
  const std::string file = tmp.path() + "/gold.mtlx";
  const auto stdout_run = run_command(cli() + " -q presets gold --format mtlx");
  const auto file_run = run_command(cli() + " -q presets gold --format mtlx --out '" + file + "'");
  ASSERT_EQ(file_run.status, 0) << file_run.err;
  EXPECT_EQ(file_run.out, "");
  std::ifstream in(file, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), stdout_run.out);
  const auto missing = run_command(cli() + " presets gold --out '" + tmp.path() + "/no/x.csv'");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/no"));
}

// A material covering less than 0.99 of the visible is refused by default, with the option that
// accepts it named.
TEST(ForgivingCli, LowCoverageRefusedUnlessLowered) {
  const auto r = run_command(cli() + " presets main/Au/nk/Ordal");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("below --min-coverage 0.99"), std::string::npos) << r.err;
  EXPECT_EQ(run_command(cli() + " -q --min-coverage 0 presets main/Au/nk/Ordal").status, 0);
}

// Every material of a document has a name of its own: a page named twice is kept once, and two
// files with one name are told apart by one suffix in every format, with a warning.
TEST(ForgivingCli, DocumentNamesAreUnique) {
  test::TempDir tmp;
  const std::string a = tmp.file("a/Cu.csv", "lambda_nm,n,k\n350,0.3,3\n850,0.3,5\n");
  const std::string b = tmp.file("b/Cu.csv", "lambda_nm,n,k\n350,0.4,3\n850,0.4,5\n");
  const auto r =
      run_command(cli() + " --space lin_rec709 presets 'main/Au/nk/J*' main/Au/nk/Johnson '" + a +
                  "' '" + b + "' --format gltf");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("skipped main/Au/nk/Johnson: named more than once: kept once"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("another material is already named 'Cu': this one is 'Cu_2'"),
            std::string::npos)
      << r.err;
  std::vector<std::string> names;
  for (std::size_t at = r.out.find("\"name\": \""); at != std::string::npos;
       at = r.out.find("\"name\": \"", at + 1))
    names.push_back(r.out.substr(at + 9, r.out.find('"', at + 9) - at - 9));
  EXPECT_EQ(names, (std::vector<std::string>{"main/Au/nk/Johnson", "Cu", "Cu_2"}));
}

// library --out replaces its folder as a whole: no stale file of an earlier run survives, and a
// folder it did not write is refused before any work.
TEST(ForgivingCli, LibraryReplacesItsFolderAndRefusesAForeignOne) {
  test::TempDir tmp;
  const std::string out = tmp.path() + "/lib";
  ASSERT_EQ(run_command(cli() + " -q library 'main/Au/nk/Johnson' --no-gallery --out '" + out + "'")
                .status,
            0);
  tmp.file("lib/stale.csv", "old\n");
  ASSERT_EQ(run_command(cli() + " -q library 'main/Ag/nk/Johnson' --no-gallery --out '" + out + "'")
                .status,
            0);
  EXPECT_FALSE(std::filesystem::exists(out + "/stale.csv"));
  EXPECT_TRUE(std::filesystem::exists(out + "/library.csv"));
  const std::string foreign = tmp.file("mine/notes.txt", "keep me\n");
  const auto r =
      run_command(cli() + " library 'main/Ag/nk/Johnson' --out '" + tmp.path() + "/mine'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not empty and not a folder Fresnel Lab wrote"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(foreign));
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/mine/library.csv"));
}

// render reports its progress on stderr (a line per tenth of the rows when stderr is a file);
// -q silences it.
TEST(ForgivingCli, RenderReportsProgressUnlessQuiet) {
  test::TempDir tmp;
  const std::string args = " render gold --size 41 --samples 2 --out '" + tmp.path() + "/g.exr'";
  const auto r = run_command(cli() + args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("render: rows 41/41"), std::string::npos) << r.err;
  EXPECT_GE(std::count(r.err.begin(), r.err.end(), '\n'), 10) << r.err;
  const auto quiet = run_command(cli() + " -q" + args);
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

TEST(NameChoice, MatchesIgnoringCaseAndSeparatorsAndSuggestsTheCanonicalName) {
  const std::vector<NameChoice> choices{{"lin_rec709", {"lin_srgb"}}, {"acescg", {}}};
  EXPECT_EQ(match_name("LIN-SRGB", choices), "lin_rec709");
  EXPECT_EQ(match_name("ACEScg", choices), "acescg");
  EXPECT_EQ(match_name("rec709", choices), std::nullopt);
  EXPECT_EQ(unknown_name_message("colour space", "lin_srbg", choices),
            "unknown colour space 'lin_srbg': did you mean 'lin_rec709'? (expected lin_rec709 or "
            "acescg)");
  EXPECT_EQ(unknown_name_message("colour space", "xyz", choices),
            "unknown colour space 'xyz' (expected lin_rec709 or acescg)");
}

}  // namespace
}  // namespace fl
