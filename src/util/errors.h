#pragma once
// Errors about what the user gave us (files, options, values): the CLI maps them to exit status 2.
#include <stdexcept>
#include <string>

namespace fl {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, const std::string& problem)
      : std::runtime_error(format(file, line, problem)), file_(std::move(file)), line_(line) {}
  explicit InputError(const std::string& problem)
      : std::runtime_error(one_line(problem)), line_(0) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& problem) {
    if (file.empty()) return one_line(problem);
    if (line > 0) return one_line(file + ":" + std::to_string(line) + ": " + problem);
    return one_line(file + ": " + problem);
  }
  // Messages are one line: control characters that came from the input (a YAML "\n" escape in
  // a quoted value, a NUL) are shown escaped.
  static std::string one_line(const std::string& s) {
    static const char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(s.size());
    for (const char ch : s) {
      const auto c = static_cast<unsigned char>(ch);
      if (c == '\n')
        out += "\\n";
      else if (c == '\r')
        out += "\\r";
      else if (c < 0x20 || c == 0x7f)
        out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
      else
        out += ch;
    }
    return out;
  }
  std::string file_;
  int line_;
};

}  // namespace fl
