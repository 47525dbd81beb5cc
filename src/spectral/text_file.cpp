#include "spectral/text_file.h"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "spectral/errors.h"

namespace fl::spectral {

namespace {

// The file's bytes.
std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot be opened for reading");
  std::string raw;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) raw.reserve(size);
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0)
    raw.append(chunk, static_cast<size_t>(in.gcount()));
  return raw;
}

// Whether a byte needs read_text_file's attention: a carriage return or a control byte other than
// a tab or a line feed.
bool special(unsigned char c) {
  return c < 0x20 && c != '\n' && c != '\t';
}

}  // namespace

std::string read_text_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw InputError(path, 0, "no such file");
  if (fs::is_directory(status)) throw InputError(path, 0, "is a directory, expected a file");
  std::string raw = read_bytes(path);
  const size_t bom = raw.size() >= 3 && static_cast<unsigned char>(raw[0]) == 0xEF &&
                             static_cast<unsigned char>(raw[1]) == 0xBB &&
                             static_cast<unsigned char>(raw[2]) == 0xBF
                         ? 3
                         : 0;
  size_t first = bom;
  while (first < raw.size() && !special(static_cast<unsigned char>(raw[first]))) ++first;
  std::string text;
  if (first == raw.size()) {
    // Nothing to convert or refuse (the usual case): the bytes as they are.
    text = bom ? raw.substr(bom) : std::move(raw);
  } else {
    text.reserve(raw.size());
    int line = 1;
    for (size_t i = bom; i < raw.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(raw[i]);
      if (c == '\r') {
        text.push_back('\n');
        if (i + 1 < raw.size() && raw[i + 1] == '\n') ++i;
        ++line;
        continue;
      }
      if (c == '\n') ++line;
      if (special(c))
        throw InputError(path, line,
                         "binary data (control byte " + std::to_string(c) + "), expected text");
      text.push_back(static_cast<char>(c));
    }
  }
  if (trim(text).empty()) throw InputError(path, 0, "file is empty");
  return text;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      if (start < text.size()) lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> split_fields(std::string_view line, std::string_view delimiters) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && delimiters.find(line[i]) != std::string_view::npos) ++i;
    if (i >= line.size()) break;
    size_t j = i;
    while (j < line.size() && delimiters.find(line[j]) == std::string_view::npos) ++j;
    out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

std::string_view trim(std::string_view s) {
  const auto ws = " \t\n\r";
  const size_t b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  const size_t e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

bool parse_finite(std::string_view field, double& value) {
  const std::string s(trim(field));
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v)) return false;
  // strtod reports underflow (a denormal such as 5.04e-317, or a result rounded to 0) with ERANGE
  // too: that is still a number. Overflow gives ±HUGE_VAL, which is not finite.
  if (errno == ERANGE && std::fabs(v) >= DBL_MIN) return false;
  value = v;
  return true;
}

}  // namespace fl::spectral
