#pragma once
// Linear RGB working spaces: primaries, white, and their XYZ matrices.
#include <string>
#include <vector>

#include "color/types.h"

namespace fl::color {

struct RgbSpace {
  std::string name;        // our name: acescg, lin_rec709, ...
  std::string description;
  Mat3 rgb_to_xyz;         // native: RGB (1,1,1) ↦ the space's white with Y = 1
  Mat3 xyz_to_rgb;
  Xyz white;               // Y = 1
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

// acescg, lin_rec709, aces2065-1, lin_rec2020, lin_p3d65. Throws InputError for others.
RgbSpace builtin_space(const std::string& name);
const std::vector<std::string>& builtin_space_names();

}  // namespace fl::color
