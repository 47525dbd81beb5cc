#pragma once
// An EXR image as a latitude-longitude environment: its shape, channels and values checked before
// any colour conversion (report/environment.h converts and exposes it).
#include <string>

#include "analysis/render/render.h"
#include "report/exr.h"

namespace fl::report {

struct EnvironmentImage {
  analysis::LatLongImage image;    // R, G, B of the file, negative values read as 0
  long long clamped_negative = 0;  // how many values were below 0 (lossy compression's ringing)
};

// The R, G, B channels of `exr` (read from `path`). InputError naming the file for a shape that is
// not 2:1 (width = 2 × height), a missing R, G or B channel, a value that is not finite, or an
// image without light (every value 0 once negative values are read as 0: exposing it to a mean
// luminance is impossible and every render would be black).
EnvironmentImage environment_image(const ExrImage& exr, const std::string& path);

}  // namespace fl::report
