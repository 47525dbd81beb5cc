#pragma once
// An EXR image as a latitude-longitude environment: its shape, channels and values checked before
// any colour conversion (analysis/render/environment_file.h converts and exposes it).
#include <string>
#include <vector>

#include "io/exr.h"

namespace fl::io {

// An equirectangular image (width = 2 × height for a full sphere of directions).
struct LatLongImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 per pixel, row-major, row 0 at the zenith
};

struct EnvironmentImage {
  LatLongImage image;              // R, G, B of the file, negative values read as 0
  long long clamped_negative = 0;  // how many values were below 0 (lossy compression's ringing)
};

// The R, G, B channels of `exr` (read from `path`). InputError naming the file for a shape that is
// not 2:1 (width = 2 × height), a missing R, G or B channel, a value that is not finite, or an
// image without light (every value 0 once negative values are read as 0: exposing it to a mean
// luminance is impossible and every render would be black).
EnvironmentImage environment_image(const ExrImage& exr, const std::string& path);

}  // namespace fl::io
