// libFuzzer target: OpenColorIO configs through Fresnel Lab's loader (SpaceLibrary::from_config,
// its checks, then every space's matrix and its conversion to a built-in space, as --ocio-config
// and --space use them).
#include <cmath>
#include <cstdlib>

#include "color/ocio.h"
#include "fuzz_common.h"
#include "util/errors.h"

namespace {

// A config can define thousands of spaces; a few are enough to reach every path.
constexpr int kMaxSpaces = 8;

bool finite(const fl::color::Mat3& m) {
  for (double v : m.m)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("OCIO_LOGGING_LEVEL", "none", 1);  // OCIO's warnings on stderr are not findings
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path(".ocio");
  fl::fuzz::write_input(path, data, size);
  try {
    const auto lib = fl::color::SpaceLibrary::from_config(path);
    const auto names = lib.names();
    for (int i = 0; i < static_cast<int>(names.size()) && i < kMaxSpaces; ++i) {
      try {
        const auto s = lib.space(names[i]);
        fl::fuzz::require(finite(s.rgb_to_xyz) && finite(s.xyz_to_rgb));
        fl::fuzz::require(finite(lib.conversion_to_builtin(names[i], "acescg")));
      } catch (const fl::InputError&) {
      }
    }
  } catch (const fl::InputError&) {
  }
  return 0;
}
