// The one writer (io/writer.h): sets replaced as a whole, the staging of dead processes recovered,
// the one rule for where outputs go.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/staging.h"
#include "io/writer.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::io {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The names in `folder`, sorted.
std::vector<std::string> names(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(folder)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// The id of a process that has ended (a child waited for).
long dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST(Writer, ReplacesASetAsAWholeAndLeavesNoStaging) {
  test::TempDir tmp;
  const std::string d = tmp.path();
  write_files_atomic({{d + "/t_1.exr", "old 1"}, {d + "/t_2.exr", "old 2"}, {d + "/t.csv", "o"}});
  write_files_atomic({{d + "/t_1.exr", "new 1"}, {d + "/t_2.exr", "new 2"}, {d + "/t.csv", "n"}});
  EXPECT_EQ(names(d), (std::vector<std::string>{"t.csv", "t_1.exr", "t_2.exr"}));
  EXPECT_EQ(slurp(d + "/t_1.exr"), "new 1");
  EXPECT_EQ(slurp(d + "/t_2.exr"), "new 2");
  EXPECT_EQ(slurp(d + "/t.csv"), "n");
}

TEST(Writer, OutputsNeverCreateMissingFolders) {
  test::TempDir tmp;
  const std::string missing = tmp.path() + "/typo/x.csv";
  try {
    write_file_atomic(missing, "x");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": the folder " + tmp.path() +
                                         "/typo does not exist (outputs never create folders)");
  }
  EXPECT_FALSE(fs::exists(tmp.path() + "/typo"));
  // An output folder (reproduce, basis) is created, but not its parent.
  EXPECT_THROW(write_files_atomic({{tmp.path() + "/a/b/f.csv", "x"}}, tmp.path() + "/a/b"),
               InputError);
  EXPECT_FALSE(fs::exists(tmp.path() + "/a"));
  write_files_atomic({{tmp.path() + "/a/f.csv", "x"}, {tmp.path() + "/a/sub/g.csv", "y"}},
                     tmp.path() + "/a");
  EXPECT_EQ(slurp(tmp.path() + "/a/sub/g.csv"), "y");
  EXPECT_EQ(names(tmp.path() + "/a"), (std::vector<std::string>{"f.csv", "sub"}));
}

// What a process killed while writing leaves is recovered by the next write into the folder: an
// uncommitted set removed, a committed one moved in (completing it), a replace_folder_atomic's
// temporaries resolved, a stray FILE.tmp.PID removed. A live process's staging is left alone.
TEST(Writer, RecoversWhatDeadProcessesLeft) {
  test::TempDir tmp;
  const fs::path d = tmp.path();
  const long dead = dead_pid(), live = static_cast<long>(::getppid());
  const auto dir = [&](const std::string& name) {
    fs::create_directories(d / name);
    return d / name;
  };
  std::ofstream(d / "set_1.exr") << "old";
  std::ofstream(d / "set_2.exr") << "old";
  const auto committed = dir(fmt::format("{}{}.3", staging::kCommitted, dead));
  std::ofstream(committed / "set_2.exr") << "new";  // set_1.exr was moved in before the kill
  std::ofstream(dir(fmt::format("{}{}.4", staging::kStaging, dead)) / "set_1.exr") << "half";
  std::ofstream(dir(fmt::format("lib.ready.{}", dead)) / "m") << "new lib";
  std::ofstream(dir("lib") / "m") << "old lib";
  std::ofstream(dir(fmt::format("gone.old.{}", dead)) / "m") << "kept";
  std::ofstream(d / fmt::format("p.csv.tmp.{}", dead)) << "partial";
  dir(fmt::format("{}{}.5", staging::kStaging, live));
  write_file_atomic((d / "other.csv").string(), "x");
  EXPECT_EQ(names(d),
            (std::vector<std::string>{fmt::format("{}{}.5", staging::kStaging, live), "gone", "lib",
                                      "other.csv", "set_1.exr", "set_2.exr"}));
  EXPECT_EQ(slurp(d / "set_2.exr"), "new");
  EXPECT_EQ(slurp(d / "lib/m"), "new lib");
  EXPECT_EQ(slurp(d / "gone/m"), "kept");  // its replacement never came: put back
}

TEST(Writer, ReplacesAFolderAsAWhole) {
  test::TempDir tmp;
  const std::string out = tmp.path() + "/lib";
  replace_folder_atomic(out, {{"a.csv", "1"}, {"strips/x.png", "2"}}, ".marker");
  replace_folder_atomic(out, {{"b.csv", "3"}}, ".marker");
  EXPECT_EQ(names(out), (std::vector<std::string>{".marker", "b.csv"}));
  EXPECT_EQ(names(tmp.path()), (std::vector<std::string>{"lib"}));
  EXPECT_THROW(replace_folder_atomic(tmp.path() + "/no/lib", {{"a", ""}}, ".marker"), InputError);
  EXPECT_FALSE(fs::exists(tmp.path() + "/no"));
}

}  // namespace
}  // namespace fl::io
