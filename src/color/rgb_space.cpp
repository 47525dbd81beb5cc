#include "color/rgb_space.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "util/errors.h"
#include "util/suggest.h"

namespace fl::color {

Mat3 rgb_to_xyz_from_primaries(Chromaticity r, Chromaticity g, Chromaticity b, Chromaticity w) {
  const Xyz xr = xyz_from_xy(r), xg = xyz_from_xy(g), xb = xyz_from_xy(b), xw = xyz_from_xy(w);
  const Mat3 p{{xr.X, xg.X, xb.X, xr.Y, xg.Y, xb.Y, xr.Z, xg.Z, xb.Z}};
  const auto s = p.inverse().apply<double>({xw.X, xw.Y, xw.Z});
  return p * Mat3::diagonal(s[0], s[1], s[2]);
}

SpaceChromaticities chromaticities_of(const RgbSpace& s) {
  const auto column = [&](int c) {
    return xy_from_xyz({s.rgb_to_xyz(0, c), s.rgb_to_xyz(1, c), s.rgb_to_xyz(2, c)});
  };
  return {column(0), column(1), column(2), xy_from_xyz(s.rgb_to_xyz * Rgb{1, 1, 1})};
}

double chromaticity_distance(const SpaceChromaticities& a, const SpaceChromaticities& b) {
  double d = 0;
  const Chromaticity pa[] = {a.red, a.green, a.blue, a.white},
                     pb[] = {b.red, b.green, b.blue, b.white};
  for (int i = 0; i < 4; ++i)
    d = std::max({d, std::abs(pa[i].x - pb[i].x), std::abs(pa[i].y - pb[i].y)});
  return d;
}

// The built-in spaces and the other names people give them: OpenColorIO 2.1's built-in config
// ("ACES - ACEScg", "Linear Rec.709 (sRGB)", ...) and common shorthands.
const std::vector<NameChoice>& builtin_space_choices() {
  static const std::vector<NameChoice> choices{
      {"acescg", {"ACES - ACEScg", "ap1", "lin_ap1"}},
      {"lin_rec709",
       {"lin_srgb", "srgb_linear", "linear_srgb", "Linear Rec.709 (sRGB)", "lin_bt709",
        "rec709_linear", "linear_rec709"}},
      {"aces2065-1", {"ACES - ACES2065-1", "ap0", "lin_ap0"}},
      {"lin_rec2020", {"Linear Rec.2020", "lin_bt2020", "rec2020_linear", "linear_rec2020"}},
      {"lin_p3d65", {"Linear P3-D65", "lin_p3", "lin_displayp3", "linear_p3d65"}}};
  return choices;
}

const std::vector<std::string>& builtin_space_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& c : builtin_space_choices()) out.push_back(c.name);
    return out;
  }();
  return names;
}

std::optional<std::string> builtin_space_name(const std::string& typed) {
  return match_name(typed, builtin_space_choices());
}

RgbSpace builtin_space(const std::string& typed) {
  const auto canonical = builtin_space_name(typed);
  if (!canonical)
    throw InputError(unknown_name_message("colour space", typed, builtin_space_choices()) +
                     "; or give --ocio-config and a space of that config");
  const std::string& name = *canonical;
  // Primaries: ACES S-2014-004 (AP1), S-2008-001 (AP0), ITU-R BT.709, BT.2020, SMPTE EG 432-1.
  const Chromaticity aces_white{0.32168, 0.33767}, d65{0.3127, 0.3290};
  auto make = [&](const char* desc, Chromaticity r, Chromaticity g, Chromaticity b,
                  Chromaticity w) {
    RgbSpace s;
    s.reference_illuminant = w.x == aces_white.x ? "D60" : "D65";
    s.builtin_equivalent = name;
    s.name = name;
    s.description = desc;
    s.rgb_to_xyz = rgb_to_xyz_from_primaries(r, g, b, w);
    s.xyz_to_rgb = s.rgb_to_xyz.inverse();
    s.white = xyz_from_xy(w);
    return s;
  };
  if (name == "acescg")
    return make("ACEScg (AP1 primaries, ACES white)", {0.713, 0.293}, {0.165, 0.830},
                {0.128, 0.044}, aces_white);
  if (name == "aces2065-1")
    return make("ACES2065-1 (AP0 primaries, ACES white)", {0.7347, 0.2653}, {0.0, 1.0},
                {0.0001, -0.0770}, aces_white);
  if (name == "lin_rec709")
    return make("linear Rec.709 / sRGB primaries, D65", {0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06},
                d65);
  if (name == "lin_rec2020")
    return make("linear Rec.2020, D65", {0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, d65);
  if (name == "lin_p3d65")
    return make("linear Display P3 (P3 primaries, D65)", {0.680, 0.320}, {0.265, 0.690},
                {0.150, 0.060}, d65);
  throw std::logic_error("builtin_space: " + name + " has no primaries");
}

}  // namespace fl::color
