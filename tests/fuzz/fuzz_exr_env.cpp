// libFuzzer target: EXR environments (read_exr, then environment_image: the latitude-longitude
// shape, R, G, B channels, finite values, not all black), as `render --env` reads them.
#include <cmath>

#include "fuzz_common.h"
#include "io/environment_image.h"
#include "io/exr.h"
#include "util/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path(".exr");
  fl::fuzz::write_input(path, data, size);
  try {
    const auto exr = fl::io::read_exr(path);
    if (exr.chromaticities)
      for (float v : *exr.chromaticities) fl::fuzz::require(std::isfinite(v));
    const auto env = fl::io::environment_image(exr, path);
    fl::fuzz::require(env.image.width == 2 * env.image.height && env.image.height > 0);
    fl::fuzz::require(env.image.rgb.size() == 3 * static_cast<size_t>(env.image.width) *
                                                  static_cast<size_t>(env.image.height));
    bool lit = false;
    for (float v : env.image.rgb) {
      fl::fuzz::require(std::isfinite(v) && v >= 0.0f);
      lit = lit || v > 0.0f;
    }
    fl::fuzz::require(lit);
  } catch (const fl::InputError&) {
  }
  return 0;
}
