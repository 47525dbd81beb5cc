#include "spectral/text_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "util/errors.h"

namespace fl::spectral {

namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, expected a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), expected a regular file";
  if (S_ISCHR(mode)) return "is a character device, expected a regular file";
  if (S_ISBLK(mode)) return "is a block device, expected a regular file";
  if (S_ISSOCK(mode)) return "is a socket, expected a regular file";
  return "is not a regular file";
}

std::string limit_text(std::uintmax_t max_bytes) {
  return max_bytes % (1 << 20) == 0 ? fmt::format("{} MiB", max_bytes >> 20)
                                    : fmt::format("{} bytes", max_bytes);
}

void check_status(const std::string& path, const struct stat& st, std::uintmax_t max_bytes) {
  if (!S_ISREG(st.st_mode)) throw InputError(path, 0, kind_of(st.st_mode));
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
    throw InputError(path, 0,
                     fmt::format("is {} bytes, more than the {} an input file may hold",
                                 static_cast<std::uintmax_t>(st.st_size), limit_text(max_bytes)));
}

// Closes a file descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// Whether a byte needs read_text_file's attention: a carriage return or a control byte other than
// a tab or a line feed.
bool special(unsigned char c) {
  return (c < 0x20) & (c != '\n') & (c != '\t');
}

// Whether any byte of s is special: a loop without an early exit, so it runs in SIMD lanes.
bool any_special(std::string_view s) {
  std::uint8_t any = 0;
  for (const char c : s) any |= static_cast<std::uint8_t>(special(static_cast<unsigned char>(c)));
  return any != 0;
}

}  // namespace

void check_input_file(const std::string& path, std::uintmax_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) throw InputError(path, 0, "no such file");
    throw InputError(path, 0, fmt::format("cannot be read ({})", std::strerror(errno)));
  }
  check_status(path, st, max_bytes);
}

std::string read_input_bytes(const std::string& path, std::uintmax_t max_bytes) {
  check_input_file(path, max_bytes);
  // O_NONBLOCK: should the path have become a FIFO since the check, open() does not wait for a
  // writer; fstat then refuses it.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0)
    throw InputError(path, 0,
                     fmt::format("cannot be opened for reading ({})", std::strerror(errno)));
  struct stat st {};
  if (::fstat(file.fd, &st) != 0)
    throw InputError(path, 0, fmt::format("cannot be read ({})", std::strerror(errno)));
  check_status(path, st, max_bytes);
  std::string raw;
  raw.reserve(static_cast<size_t>(st.st_size));
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = ::read(file.fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path, 0, fmt::format("cannot be read ({})", std::strerror(errno)));
    if (n == 0) break;
    if (raw.size() + static_cast<size_t>(n) > max_bytes)  // grew while being read
      throw InputError(path, 0,
                       fmt::format("grew past the {} an input file may hold while being read",
                                   limit_text(max_bytes)));
    raw.append(chunk, static_cast<size_t>(n));
  }
  return raw;
}

std::vector<std::string> list_folder(const std::string& dir, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(dir, ec);
  if (!fs::exists(status)) throw InputError(dir, 0, what + " not found");
  if (!fs::is_directory(status)) throw InputError(dir, 0, what + " is not a folder");
  std::vector<std::string> out;
  fs::directory_iterator it(dir, ec), end;
  for (; !ec && it != end; it.increment(ec)) out.push_back(it->path().string());
  if (ec) throw InputError(dir, 0, fmt::format("{} cannot be listed ({})", what, ec.message()));
  std::sort(out.begin(), out.end());
  return out;
}

std::string read_text_file(const std::string& path) {
  std::string raw = read_input_bytes(path);
  const size_t bom = raw.size() >= 3 && static_cast<unsigned char>(raw[0]) == 0xEF &&
                             static_cast<unsigned char>(raw[1]) == 0xBB &&
                             static_cast<unsigned char>(raw[2]) == 0xBF
                         ? 3
                         : 0;
  std::string text;
  if (!any_special(std::string_view(raw).substr(bom))) {
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

namespace {

// A set of bytes, one bit each: a field's end is one test per byte.
class ByteSet {
 public:
  explicit ByteSet(std::string_view bytes) {
    for (const char c : bytes) {
      const auto b = static_cast<unsigned char>(c);
      bits_[b >> 6] |= std::uint64_t{1} << (b & 63);
    }
  }
  bool has(char c) const {
    const auto b = static_cast<unsigned char>(c);
    return (bits_[b >> 6] >> (b & 63)) & 1;
  }

 private:
  std::array<std::uint64_t, 4> bits_{};
};

// The next field of `line` at or after `i` (empty at the end); `i` moves past it.
std::string_view next_field(std::string_view line, const ByteSet& delimiters, size_t& i) {
  while (i < line.size() && delimiters.has(line[i])) ++i;
  const size_t start = i;
  while (i < line.size() && !delimiters.has(line[i])) ++i;
  return line.substr(start, i - start);
}

}  // namespace

std::vector<std::string_view> split_fields(std::string_view line,
                                           std::string_view delimiter_bytes) {
  std::vector<std::string_view> out;
  const ByteSet delimiters(delimiter_bytes);
  size_t i = 0;
  for (auto f = next_field(line, delimiters, i); !f.empty(); f = next_field(line, delimiters, i))
    out.push_back(f);
  return out;
}

size_t split_fields(std::string_view line, std::string_view delimiter_bytes,
                    std::span<std::string_view> out) {
  const ByteSet delimiters(delimiter_bytes);
  size_t count = 0, i = 0;
  for (auto f = next_field(line, delimiters, i); !f.empty(); f = next_field(line, delimiters, i)) {
    if (count < out.size()) out[count] = f;
    ++count;
  }
  return count;
}

std::string_view trim(std::string_view s) {
  const auto ws = " \t\n\r";
  const size_t b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  const size_t e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

bool parse_finite(std::string_view field, double& value) {
  std::string_view s = trim(field);
  // A leading '+' is a sign, as for strtod; from_chars takes '-' alone.
  if (s.size() > 1 && s.front() == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  if (s.empty()) return false;
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (end != s.data() + s.size()) return false;
  if (ec == std::errc::result_out_of_range) {
    // Out of range: overflow (not a number) or underflow below the smallest denormal, which
    // rounds to a signed zero and is still a number. The exponent's sign tells them apart.
    const size_t e = s.find_first_of("eE");
    if (e == std::string_view::npos || e + 1 >= s.size() || s[e + 1] != '-') return false;
    v = s.front() == '-' ? -0.0 : 0.0;
  } else if (ec != std::errc{} || !std::isfinite(v)) {
    return false;
  }
  value = v;
  return true;
}

}  // namespace fl::spectral
