#include "analysis/render/environment_file.h"

#include <fmt/format.h>

#include "io/environment_image.h"
#include "io/exr.h"
#include "util/errors.h"

namespace fl::analysis {
namespace {

// Agreement of an EXR chromaticities attribute (float) with a space's primaries and white.
constexpr double kChromaticityTol = 1e-3;

// The colour space the file's pixels are in, and how that was decided.
std::pair<std::string, std::string> file_space(const Context& ctx, const io::ExrImage& exr,
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

LoadedEnvironment load_environment(const Context& ctx, const std::string& path,
                                   const std::string& space, double rotation_deg,
                                   double exposure_ev) {
  const io::ExrImage exr =
      io::read_exr(path);  // InputError for what is not a bounded regular EXR file
  auto env = io::environment_image(exr, path);
  const auto [space_name, basis] = file_space(ctx, exr, path, space);
  double scale = 1;
  try {
    auto map =
        environment_map(ctx, std::move(env.image), space_name, rotation_deg, exposure_ev, scale);
    return {std::move(map), space_name,           basis,       exr.width,
            exr.height,     env.clamped_negative, exposure_ev, scale};
  } catch (const InputError& e) {
    throw InputError(path, 0, e.what());
  }
}

}  // namespace fl::analysis
