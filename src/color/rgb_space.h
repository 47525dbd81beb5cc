#pragma once
// Linear RGB working spaces: primaries, white, and their XYZ matrices.
#include <optional>
#include <string>
#include <vector>

#include "color/matrix.h"

namespace fl::color {

struct RgbSpace {
  std::string name;  // our name: acescg, lin_rec709, ...
  std::string description;
  Mat3 rgb_to_xyz;  // native: RGB (1,1,1) ↦ the space's white with Y = 1
  Mat3 xyz_to_rgb;
  Xyz white;  // Y = 1
  // The space's reference white illuminant (the spectrum whose white the space's white is): D60 for
  // the ACES spaces, D65 for Rec.709, Rec.2020 and P3-D65.
  std::string reference_illuminant;
  // Where the white came from, for report headers ("built-in", or how an OCIO space's was found).
  std::string white_source = "built-in";
  // The built-in space this one is (its own name, or the one an OCIO space's matrix equals; empty
  // for others).
  std::string builtin_equivalent;
};

// RGB → XYZ matrix from primaries and white chromaticities (SMPTE RP 177).
Mat3 rgb_to_xyz_from_primaries(Chromaticity r, Chromaticity g, Chromaticity b, Chromaticity white);

// The chromaticities of a space's primaries (the columns of its RGB → XYZ matrix) and of its white
// (the image of RGB (1, 1, 1)), as an OpenEXR chromaticities attribute states them.
struct SpaceChromaticities {
  Chromaticity red, green, blue, white;
};
SpaceChromaticities chromaticities_of(const RgbSpace& space);
// Largest difference in x or y between two sets of chromaticities.
double chromaticity_distance(const SpaceChromaticities& a, const SpaceChromaticities& b);

// acescg, lin_rec709, aces2065-1, lin_rec2020, lin_p3d65 (or an alias builtin_space_name
// accepts). Throws InputError for others.
RgbSpace builtin_space(const std::string& name);
const std::vector<std::string>& builtin_space_names();
// The built-in space `typed` names, ignoring case and accepting the usual aliases ("lin_srgb",
// "ACES - ACEScg"); nullopt when it names none.
std::optional<std::string> builtin_space_name(const std::string& typed);

}  // namespace fl::color
