#include "io/environment.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/exr.h"
#include "spectral/errors.h"

namespace fl::report {
namespace {

// Agreement of an EXR chromaticities attribute (float) with a space's primaries and white.
constexpr double kChromaticityTol = 1e-3;

int channel_index(const ExrImage& exr, const std::string& path, const char* name) {
  const auto it = std::find(exr.channels.begin(), exr.channels.end(), name);
  if (it == exr.channels.end())
    throw InputError(path, 0, fmt::format("no {} channel: an environment needs R, G and B", name));
  return static_cast<int>(it - exr.channels.begin());
}

// The colour space the file's pixels are in, and how that was decided.
std::pair<std::string, std::string> file_space(const analysis::Context& ctx, const ExrImage& exr,
                                               const std::string& path,
                                               const std::string& requested) {
  if (!requested.empty()) {
    ctx.spaces().space(requested);  // InputError for an unknown name
    return {requested, "--env-space"};
  }
  if (!exr.chromaticities)
    return {"lin_rec709", "OpenEXR's default: the file states no chromaticities"};
  const auto& c = *exr.chromaticities;
  const color::SpaceChromaticities stated{{c[0], c[1]}, {c[2], c[3]}, {c[4], c[5]}, {c[6], c[7]}};
  const std::string name = ctx.spaces().space_with_chromaticities(stated, kChromaticityTol);
  if (name.empty())
    throw InputError(
        path, 0,
        fmt::format(
            "chromaticities (r {:.4f} {:.4f}, g {:.4f} {:.4f}, b {:.4f} {:.4f}, w {:.4f} {:.4f}) "
            "match no known colour space; name one with --env-space",
            c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]));
  return {name, "the file's chromaticities"};
}

}  // namespace

std::string LoadedEnvironment::description() const {
  return fmt::format(
      "{} × {} latitude-longitude, {} ({}), rotated {:g}°, exposed to mean luminance 2^{:g} (× "
      "{:.4g})",
      width, height, space, space_basis, map.rotation_deg(), exposure_ev, scale);
}

LoadedEnvironment load_environment(const analysis::Context& ctx, const std::string& path,
                                   const std::string& space, double rotation_deg,
                                   double exposure_ev) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError(path, 0, "no such environment file");
  const ExrImage exr = read_exr(path);
  if (exr.width != 2 * exr.height)
    throw InputError(
        path, 0,
        fmt::format("{} × {} is not a latitude-longitude map (width must be twice the height)",
                    exr.width, exr.height));
  const int ch[3] = {channel_index(exr, path, "R"), channel_index(exr, path, "G"),
                     channel_index(exr, path, "B")};
  const auto [space_name, basis] = file_space(ctx, exr, path, space);
  analysis::LatLongImage img;
  img.width = exr.width;
  img.height = exr.height;
  img.rgb.resize(3 * static_cast<size_t>(exr.width) * exr.height);
  long long clamped = 0;
  const size_t nc = exr.channels.size();
  for (size_t k = 0; k < img.rgb.size() / 3; ++k)
    for (int c = 0; c < 3; ++c) {
      const float v = exr.pixels[k * nc + ch[c]];
      if (!std::isfinite(v))
        throw InputError(path, 0,
                         fmt::format("pixel ({}, {}) has a non-finite {} value", k % exr.width,
                                     k / exr.width, "RGB"[c]));
      if (v < 0.0f) ++clamped;
      img.rgb[3 * k + c] = std::max(0.0f, v);
    }
  double scale = 1;
  auto map =
      analysis::environment_map(ctx, std::move(img), space_name, rotation_deg, exposure_ev, scale);
  return {std::move(map), space_name, basis, exr.width, exr.height, clamped, exposure_ev, scale};
}

}  // namespace fl::report
