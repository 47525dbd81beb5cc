#pragma once
// Text cut short for a message, so that a 100 KB name does not fill the terminal.
#include <string>

namespace fl {

// The longest error line the command line prints, in bytes.
inline constexpr size_t kMaxErrorLine = 1000;

// `s` cut to about `max` bytes: its head and tail around "…(N bytes)…", cut at UTF-8 character
// boundaries.
inline std::string truncated(const std::string& s, size_t max = 200) {
  if (s.size() <= max) return s;
  const auto boundary = [&](size_t i) {  // back to the start of the character holding byte i
    while (i > 0 && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) --i;
    return i;
  };
  const size_t head = boundary(max / 2), tail = boundary(s.size() - max / 2);
  return s.substr(0, head) + "\xe2\x80\xa6(" + std::to_string(tail - head) + " bytes)\xe2\x80\xa6" +
         s.substr(tail);
}

}  // namespace fl
