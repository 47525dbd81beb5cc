#include "io/environment_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/errors.h"

namespace fl::io {
namespace {

int channel_index(const ExrImage& exr, const std::string& path, const char* name) {
  const auto it = std::find(exr.channels.begin(), exr.channels.end(), name);
  if (it == exr.channels.end())
    throw InputError(path, 0, fmt::format("no {} channel: an environment needs R, G and B", name));
  return static_cast<int>(it - exr.channels.begin());
}

}  // namespace

EnvironmentImage environment_image(const ExrImage& exr, const std::string& path) {
  if (exr.height <= 0 || exr.width != 2 * exr.height)
    throw InputError(
        path, 0,
        fmt::format("{} × {} is not a latitude-longitude map (width must be twice the height)",
                    exr.width, exr.height));
  const int ch[3] = {channel_index(exr, path, "R"), channel_index(exr, path, "G"),
                     channel_index(exr, path, "B")};
  EnvironmentImage out;
  auto& img = out.image;
  img.width = exr.width;
  img.height = exr.height;
  img.rgb.resize(3 * static_cast<size_t>(exr.width) * static_cast<size_t>(exr.height));
  const size_t nc = exr.channels.size();
  bool lit = false;
  for (size_t k = 0; k < img.rgb.size() / 3; ++k)
    for (int c = 0; c < 3; ++c) {
      const float v = exr.pixels[k * nc + static_cast<size_t>(ch[c])];
      if (!std::isfinite(v))
        throw InputError(path, 0,
                         fmt::format("pixel ({}, {}) has a non-finite {} value", k % exr.width,
                                     k / exr.width, "RGB"[c]));
      if (v < 0.0f) ++out.clamped_negative;
      img.rgb[3 * k + c] = std::max(0.0f, v);
      lit = lit || v > 0.0f;
    }
  if (!lit)
    throw InputError(path, 0,
                     out.clamped_negative > 0
                         ? "no light: every R, G and B value is 0 or negative (negative values "
                           "read as 0), so every render would be black"
                         : "no light: every R, G and B value is 0, so every render would be black");
  return out;
}

}  // namespace fl::io
