// The bad-input corpus (tests/bad_input/, listed in manifest.tsv) run through the CLI.
// Every bad input must give exit status 2, exactly one stderr line naming the file (and line) and
// the problem, nothing on stdout and no output file; byte-order marks and CRLF line endings are
// valid input (tests/good_input/).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "csv_reader.h"

namespace fs = std::filesystem;

namespace {

const std::string kBadDir = FL_TESTS_DIR "/bad_input";
const std::string kGoodDir = FL_TESTS_DIR "/good_input";

struct Case {
  std::string reader, file, command, fragment;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.reader << "/" << c.file << " [" << c.command << "]";
}

std::vector<Case> load_manifest() {
  std::vector<Case> out;
  for (const auto& f : fl::test::csv_file_rows(kBadDir + "/manifest.tsv",
                                               {.separator = '\t', .skip_comments = true})) {
    if (f.size() != 4) throw std::runtime_error("manifest.tsv: bad row: " + f[0]);
    out.push_back({f[0], f[1], f[2], f[3]});
  }
  return out;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quote(const std::string& s) {
  return "'" + s + "'";
}

struct Result {
  int status = -1;
  std::string out, err;
};

// Runs the CLI with `args` (already quoted) and optional environment assignments.
Result run_cli(const fs::path& work, const std::string& args, const std::string& env = "") {
  const fs::path out = work / "stdout.txt", err = work / "stderr.txt";
  const std::string cmd =
      env + " " + quote(FL_CLI) + " " + args + " >" + quote(out) + " 2>" + quote(err);
  const int rc = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + (WIFSIGNALED(rc) ? WTERMSIG(rc) : 0);
  r.out = read_all(out);
  r.err = read_all(err);
  return r;
}

// A scratch folder per test, removed afterwards.
struct Scratch {
  fs::path dir;
  explicit Scratch(const std::string& name) {
    dir = fs::temp_directory_path() / ("fl_bad_input_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// Puts the corpus entry (file, directory or nothing for <missing>) at `dest`.
void install(const Case& c, const fs::path& dest) {
  fs::create_directories(dest.parent_path());
  fs::remove_all(dest);
  if (c.file == "<missing>") return;
  const fs::path src = fs::path(kBadDir) / c.reader / c.file;
  if (fs::is_directory(src))
    fs::create_directories(dest);
  else
    fs::copy_file(src, dest);
}

size_t count_files(const fs::path& dir) {
  if (!fs::exists(dir)) return 0;
  size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

std::string test_name(const testing::TestParamInfo<Case>& info) {
  std::string s = info.param.reader + "_" + info.param.file + "_" + info.param.command;
  for (auto& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s + "_" + std::to_string(info.index);
}

class BadInput : public testing::TestWithParam<Case> {};

TEST_P(BadInput, ExitsWithStatus2AndOneLineNamingTheFile) {
  const Case& c = GetParam();
  Scratch s(test_name({c, 0}));
  const fs::path out_dir = s.dir / "out";
  const fs::path empty_catalog = s.dir / "empty_catalog";
  fs::create_directories(empty_catalog);
  std::string file;  // the path the tool is given
  std::string args, env;
  bool writes_output = true;
  if (c.command == "curve") {
    file = c.file == "<missing>" ? (s.dir / "does_not_exist.yml").string()
                                 : kBadDir + "/" + c.reader + "/" + c.file;
    if (c.reader == "csv" && c.file == "<missing>") file = (s.dir / "does_not_exist.csv").string();
    args = "--materials " + quote(empty_catalog) + " curve " + quote(file);
    writes_output = false;
  } else if (c.command == "db-reproduce") {
    const fs::path db = s.dir / "db", catalog = s.dir / "catalog";
    file = (db / "data/main/Bad/nk/Bad.yml").string();
    install(c, file);
    fs::create_directories(catalog);
    std::ofstream(catalog / "bad.yml") << "name: Bad\nclass: metal\nsource: main/Bad/nk/Bad\n";
    args = "--db " + quote(db) + " --materials " + quote(catalog) + " reproduce --out " +
           quote(out_dir);
  } else if (c.command == "catalog-reproduce") {
    const fs::path catalog = s.dir / "catalog";
    if (c.file == "<missing>") {
      file = catalog.string();
    } else {
      file = (catalog / "bad.yml").string();
      install(c, file);
    }
    args = "--db " + quote(kGoodDir + "/db") + " --materials " + quote(catalog) +
           " reproduce --out " + quote(out_dir);
  } else if (c.command.rfind("ocio:", 0) == 0) {  // ocio:SPACE, the config's working space
    file = kBadDir + "/" + c.reader + "/" + c.file;
    args = "--materials " + quote(empty_catalog) + " --ocio-config " + quote(file) + " --space " +
           quote(c.command.substr(5)) + " curve " + quote(kGoodDir + "/nk_no_k.csv");
    writes_output = false;
  } else if (c.command == "render-env") {  // environment maps
    file = kBadDir + "/" + c.reader + "/" + c.file;
    fs::create_directories(out_dir);  // an output's folder must exist
    args = "--materials " + quote(empty_catalog) + " render " + quote(kGoodDir + "/nk_no_k.csv") +
           " --env " + quote(file) + " --size 9 --samples 1 --out " + quote(out_dir / "r.exr");
  } else if (c.command == "plan") {  // scene files
    file = c.file == "<missing>" ? (s.dir / "does_not_exist.yaml").string()
                                 : kBadDir + "/" + c.reader + "/" + c.file;
    args = "plan " + quote(file);
    writes_output = false;
  } else {
    FAIL() << "unknown command '" << c.command << "' in manifest.tsv";
  }
  const Result r = run_cli(s.dir, args, env);
  std::string want = c.fragment;
  if (const auto p = want.find("{file}"); p != std::string::npos) want.replace(p, 6, file);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.back(), '\n');
  EXPECT_EQ(r.err.rfind("fresnel-lab: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(want), std::string::npos) << "expected '" << want << "' in: " << r.err;
  if (writes_output) {
    EXPECT_EQ(count_files(out_dir), 0u) << "partial output left in " << out_dir;
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, testing::ValuesIn(load_manifest()), test_name);

TEST(BadInputCorpus, EveryCorpusEntryIsInTheManifestAndThereAreAtLeast30) {
  std::set<std::string> listed;
  for (const auto& c : load_manifest())
    if (c.file != "<missing>") listed.insert(c.reader + "/" + c.file);
  std::set<std::string> present;
  for (const char* reader : {"ri_yaml", "csv", "text", "sopra", "spd", "wvase", "decimal_comma",
                             "energy", "catalog", "scene", "ocio", "env"})
    for (const auto& e : fs::directory_iterator(kBadDir + "/" + reader))
      present.insert(std::string(reader) + "/" + e.path().filename().string());
  EXPECT_EQ(listed, present);
  constexpr size_t kMinimumCorpus = 30;
  EXPECT_GE(present.size(), kMinimumCorpus);
}

// ---- Inputs that are not regular files, and folders that cannot be listed. ----

// The one-line error of a run that must be refused as bad input (exit 2, nothing on stdout).
std::string refused(const Result& r) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  return r.err;
}

TEST(SpecialInputs, FifoAndDevicesAreRefusedWithoutReading) {
  Scratch s("special");
  const fs::path fifo = s.dir / "pipe.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Nothing ever writes to the FIFO: a tool that opened it would wait until CTest's timeout.
  EXPECT_NE(refused(run_cli(s.dir, "curve " + quote(fifo)))
                .find(fifo.string() + ": is a FIFO (named pipe), expected a regular file"),
            std::string::npos);
  EXPECT_NE(refused(run_cli(s.dir, "curve /dev/zero"))
                .find("/dev/zero: is a character device, expected a regular file"),
            std::string::npos);
  EXPECT_NE(refused(run_cli(s.dir, "--ocio-config " + quote(fifo) + " --space ACEScg curve gold"))
                .find(fifo.string() + ": is a FIFO"),
            std::string::npos);
  const fs::path fifo_exr = s.dir / "pipe.exr";
  ASSERT_EQ(::mkfifo(fifo_exr.c_str(), 0600), 0);
  fs::create_directories(s.dir / "out");  // an output's folder must exist
  EXPECT_NE(refused(run_cli(s.dir, "render gold --env " + quote(fifo_exr) + " --out " +
                                       quote(s.dir / "out/r.exr")))
                .find(fifo_exr.string() + ": is a FIFO"),
            std::string::npos);
  EXPECT_EQ(count_files(s.dir / "out"), 0u);
}

TEST(SpecialInputs, AnUnreadableCatalogFolderIsBadInput) {
  Scratch s("unreadable");
  const fs::path catalog = s.dir / "catalog";
  fs::create_directories(catalog);
  std::ofstream(catalog / "glass.yml") << "name: Glass\nclass: dielectric\nconstant: {n: 1.5}\n";
  fs::permissions(catalog, fs::perms::none);
  fs::permissions(s.dir, fs::perms::all);  // the unprivileged user writes stdout.txt here
  // Permissions do not bind root: run as nobody then (util-linux's setpriv).
  const std::string as =
      ::geteuid() == 0 ? "setpriv --reuid=nobody --regid=nogroup --clear-groups " : "";
  if (!as.empty() && std::system("command -v setpriv >/dev/null") != 0)
    GTEST_SKIP() << "running as root without setpriv";
  const Result r = run_cli(s.dir, "--materials " + quote(catalog) + " materials", as);
  fs::permissions(catalog, fs::perms::owner_all);
  EXPECT_NE(refused(r).find(catalog.string() +
                            ": material catalog folder cannot be listed (Permission denied)"),
            std::string::npos)
      << r.err;
}

TEST(SpecialInputs, CatalogNamesAreUnique) {
  Scratch s("duplicate");
  const fs::path catalog = s.dir / "catalog";
  fs::create_directories(catalog);
  std::ofstream(catalog / "a.yml") << "name: Glass\nclass: dielectric\nconstant: {n: 1.5}\n";
  std::ofstream(catalog / "b.yml") << "class: dielectric\nname: GLASS\nconstant: {n: 1.6}\n";
  const std::string want = (catalog / "b.yml").string() +
                           ":2: name 'GLASS' is already the name of " +
                           (catalog / "a.yml").string() + ":1";
  for (const char* command : {"materials", "presets glass"})
    EXPECT_NE(refused(run_cli(s.dir, "--materials " + quote(catalog) + " " + command)).find(want),
              std::string::npos)
        << command;
}

// ---- Valid inputs: BOM, CRLF and CR line endings change nothing. ----

// A curve CSV without its material column (the file's name, which differs between the copies).
std::string without_material(const std::string& csv) {
  std::string out;
  for (auto cells : fl::test::csv_rows(csv)) {
    if (cells.size() > 8) cells.erase(cells.begin() + 8);
    for (size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + cells[i];
    out += "\n";
  }
  return out;
}

TEST(GoodInput, BomAndCrlfDatabaseFileGivesTheSameCurveAsThePlainFile) {
  Scratch s("good_ri");
  const fs::path plain = s.dir / "plain.yml";
  {
    // The same rows as good_input/ri_bom_crlf.yml, written without BOM and with LF endings.
    std::string text = read_all(kGoodDir + "/ri_bom_crlf.yml");
    ASSERT_EQ(text.substr(0, 3), "\xEF\xBB\xBF");
    ASSERT_NE(text.find("\r\n"), std::string::npos);
    text.erase(0, 3);
    text.erase(std::remove(text.begin(), text.end(), '\r'), text.end());
    std::ofstream(plain, std::ios::binary) << text;
  }
  const Result a = run_cli(s.dir, "curve " + quote(plain));
  const Result b = run_cli(s.dir, "curve " + quote(kGoodDir + "/ri_bom_crlf.yml"));
  const Result c = run_cli(s.dir, "curve " + quote(kGoodDir + "/ri_bom.yml"));
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_GT(std::count(a.out.begin(), a.out.end(), '\n'), 90);  // header + 91 angles
  EXPECT_EQ(without_material(a.out), without_material(b.out));
  EXPECT_EQ(without_material(a.out), without_material(c.out));
  EXPECT_EQ(a.out.find("nan"), std::string::npos);
}

TEST(GoodInput, CsvWithBomCrlfOrCrOnlyIsAccepted) {
  Scratch s("good_csv");
  for (const char* f : {"nk_bom_crlf.csv", "nk_cr_only.csv", "nk_no_k.csv"}) {
    const Result r = run_cli(s.dir, "curve " + quote(kGoodDir + "/" + f));
    EXPECT_EQ(r.status, 0) << f << ": " << r.err;
    EXPECT_GT(std::count(r.out.begin(), r.out.end(), '\n'), 90) << f;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << f;
  }
  // CR-only and LF versions of the same data agree.
  const fs::path lf = s.dir / "lf.csv";
  std::string text = read_all(kGoodDir + "/nk_cr_only.csv");
  std::replace(text.begin(), text.end(), '\r', '\n');
  std::ofstream(lf, std::ios::binary) << text;
  EXPECT_EQ(without_material(run_cli(s.dir, "curve " + quote(lf)).out),
            without_material(run_cli(s.dir, "curve " + quote(kGoodDir + "/nk_cr_only.csv")).out));
}

// The same rows as a plain CSV, a WVASE .mat and a semicolon table with decimal commas give the
// same curve; photon energies in eV are read.
TEST(GoodInput, WvaseMatDecimalCommasAndEnergiesAreAccepted) {
  Scratch s("good_formats");
  const Result plain = run_cli(s.dir, "curve " + quote(kGoodDir + "/nk_gold_like.csv"));
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_GT(std::count(plain.out.begin(), plain.out.end(), '\n'), 90);
  for (const char* f : {"wvase_gold_like.mat", "nk_gold_like_decimal_comma.csv"}) {
    const Result r = run_cli(s.dir, "curve " + quote(kGoodDir + "/" + f));
    ASSERT_EQ(r.status, 0) << f << ": " << r.err;
    EXPECT_EQ(without_material(r.out), without_material(plain.out)) << f;
  }
  const Result ev = run_cli(s.dir, "curve " + quote(kGoodDir + "/nk_energy_ev.csv"));
  ASSERT_EQ(ev.status, 0) << ev.err;
  EXPECT_GT(std::count(ev.out.begin(), ev.out.end(), '\n'), 90);
  EXPECT_EQ(ev.out.find("nan"), std::string::npos);
}

TEST(GoodInput, CatalogEntriesWithBomAndCrlfLoad) {
  Scratch s("good_catalog");
  const Result r = run_cli(s.dir, "--db " + quote(kGoodDir + "/db") + " --materials " +
                                      quote(kGoodDir + "/catalog") + " materials");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Good CRLF"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Good tabulated"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\r'), std::string::npos);
  const Result t = run_cli(s.dir, "--db " + quote(kGoodDir + "/db") + " --materials " +
                                      quote(kGoodDir + "/catalog") + " table schlick");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_EQ(std::count(t.out.begin(), t.out.end(), '\n'), 3) << t.out;  // header + 2 materials
}

// The database's catalog-nk.yml names pages; a broken one stops the command (exit 2, the file and
// line in libyaml's words) instead of leaving every page unnamed.
TEST(BadInput, BrokenPageCatalogIsAnErrorNamingTheFile) {
  Scratch s("bad_page_catalog");
  const fs::path db = s.dir / "db";
  fs::copy(kGoodDir + "/db", db, fs::copy_options::recursive);
  std::ofstream(db / "catalog-nk.yml") << "- SHELF: main\n  content: [\n    - BOOK: Au\n";
  const Result r = run_cli(s.dir, "--db " + quote(db) + " pages");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find((db / "catalog-nk.yml").string() + ":"), std::string::npos) << r.err;
}

}  // namespace
