#pragma once
// Environment maps read from latitude-longitude OpenEXR files, converted into the working space.
#include <string>

#include "analysis/render/render.h"

namespace fl::analysis {

struct LoadedEnvironment {
  EnvironmentMap map;
  std::string space;        // the file's colour space (a SpaceLibrary name)
  std::string space_basis;  // how it was decided: "--env-space", "the file's chromaticities", or
                            // OpenEXR's default
  int width = 0, height = 0;
  long long clamped_negative = 0;  // pixel values below 0 read as 0
  double exposure_ev = 0,
         scale = 1;  // environment_map's exposure and the factor it applied
  std::string description() const;
};

// The R, G, B channels of a latitude-longitude EXR (width = 2 × height, OpenEXR's orientation)
// as radiance in colour space `space`, or, when `space` is empty, in the space whose primaries
// and white the file's chromaticities attribute states (within 1e-3 in x and y), or, without that
// attribute, linear Rec.709 (OpenEXR's default chromaticities); converted into the working space
// through OpenColorIO (environment_map). Negative values (lossy compression's ringing)
// are read as 0 and counted; exposed as environment_map says. InputError naming the file
// for what read_exr and environment_image refuse (not a bounded regular EXR file, missing R, G or B
// channels, a non-finite value, a shape that is not 2:1, no light), chromaticities no known space
// has, or a mean luminance in the working space that is not a positive finite number.
LoadedEnvironment load_environment(const Context& ctx, const std::string& path,
                                   const std::string& space, double rotation_deg,
                                   double exposure_ev);

}  // namespace fl::analysis
