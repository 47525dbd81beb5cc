#pragma once
// Shared libFuzzer harness helpers: the readers take paths, so each input is written to a
// per-process temporary file first. Only fl::InputError is an acceptable failure; any other
// exception escapes and libFuzzer reports it as a crash (the CLI would exit 1 instead of 2).
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fl::fuzz {

inline std::string temp_path(const char* ext) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/fl_fuzz_" + std::to_string(::getpid()) + ext;
}

inline void write_input(const std::string& path, const uint8_t* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
}

// A reader accepted the input: what it produced must be usable downstream.
inline void require(bool ok) {
  if (!ok) std::abort();
}

}  // namespace fl::fuzz
