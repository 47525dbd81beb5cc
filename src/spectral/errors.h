#pragma once
// Errors about what the user gave us (files, options, values): the CLI maps them to exit status 2.
#include <stdexcept>
#include <string>

namespace fl {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, const std::string& problem)
      : std::runtime_error(format(file, line, problem)), file_(std::move(file)), line_(line) {}
  explicit InputError(const std::string& problem) : std::runtime_error(problem), line_(0) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& problem) {
    if (file.empty()) return problem;
    if (line > 0) return file + ":" + std::to_string(line) + ": " + problem;
    return file + ": " + problem;
  }
  std::string file_;
  int line_;
};

}  // namespace fl
