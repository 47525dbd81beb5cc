#pragma once
// RGB colour-space conversions through OpenColorIO. OCIO stays inside this module: callers get
// plain matrices (computed by OCIO in double precision from its built-in transforms or a user
// config) and RgbSpace values.
#include <memory>
#include <string>
#include <vector>

#include "color/rgb_space.h"

namespace fl::color {

class SpaceLibrary {
 public:
  // Our five built-in spaces, defined to OCIO through its built-in transforms (ACES AP0/AP1 to
  // CIE-XYZ-D65 with Bradford adaptation, AP1 to linear Rec.709) and, for Rec.2020 and P3-D65
  // which OCIO 2.1 has no linear built-in for, matrices from their published primaries.
  static SpaceLibrary builtin();
  // A studio config: spaces are its colour-space names; `xyz_space` names its CIE XYZ (D65)
  // space (default: the role cie_xyz_d65_interchange, else a space called CIE-XYZ-D65).
  static SpaceLibrary from_config(const std::string& config_path, const std::string& xyz_space = "");

  // The space's native matrices and white, as OCIO sees it (linear spaces only).
  RgbSpace space(const std::string& name) const;
  // RGB in `from` → RGB in `to`. Throws InputError if the conversion is not a pure matrix.
  Mat3 conversion(const std::string& from, const std::string& to) const;
  std::vector<std::string> names() const;
  // The first of names() whose primaries and white are within `tolerance` (in x and y) of `c`;
  // empty if none (spaces that are not linear matrices are skipped).
  std::string space_with_chromaticities(const SpaceChromaticities& c, double tolerance) const;
  bool is_builtin() const { return config_path_.empty(); }
  const std::string& config_path() const { return config_path_; }

  // Linear Rec.709 → sRGB display encoding (OCIO's piecewise sRGB curve), 3 floats per pixel,
  // in place; values are clamped to [0, 1] after encoding.
  static void encode_srgb_display(std::vector<float>& rgb_linear_rec709);

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
  std::string config_path_;
};

}  // namespace fl::color
