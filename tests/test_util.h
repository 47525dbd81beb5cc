#pragma once
// Helpers shared by the tests: temporary files and running the CLI.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fl::test {

// A fresh temporary directory removed at scope exit.
class TempDir {
 public:
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "fl_test_XXXXXX").string();
    path_ = ::mkdtemp(tmpl.data());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const std::string& name, const std::string& content) const {
    const std::string p = path_ + "/" + name;
    std::filesystem::create_directories(std::filesystem::path(p).parent_path());
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

struct CommandResult {
  int status = -1;
  std::string out, err;
};

// Runs a shell command line, capturing stdout and stderr.
inline CommandResult run_command(const std::string& cmdline) {
  TempDir tmp;
  const std::string out = tmp.path() + "/out", err = tmp.path() + "/err";
  const int rc = std::system((cmdline + " >" + out + " 2>" + err).c_str());
  CommandResult r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

inline std::string cli() {
  return std::string("'") + FL_CLI + "' --db '" + FL_DEFAULT_DB + "' --materials '" + FL_MATERIALS +
         "'";
}

// n cosines evenly spaced over [0, 1], both ends included.
inline std::vector<double> cosines(int n) {
  std::vector<double> c;
  for (int i = 0; i < n; ++i) c.push_back(static_cast<double>(i) / (n - 1));
  return c;
}

}  // namespace fl::test
