#pragma once
// RGB colour-space conversions through OpenColorIO. OCIO stays inside this module: callers get
// plain matrices (computed by OCIO in double precision from its built-in transforms or a user
// config) and RgbSpace values.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "color/rgb_space.h"

namespace fl::color {

// A white for a config space, given by the user (the config's matrices are adapted to D65 and do
// not carry the space's own white): its XYZ (Y = 1), the illuminant it is the white of, and a
// phrase naming where it came from.
struct SpaceWhite {
  Xyz white;
  std::string illuminant;
  std::string source;
};

// Matrices from different configs that agree this closely are the same space: distinct gamuts in
// use differ by 1e-2 or more per entry, while OCIO's built-ins and matrices written from published
// primaries agree to about 1e-6.
inline constexpr double kBuiltinMatchTolerance = 1e-4;

class DisplayTransform;

class SpaceLibrary {
 public:
  // Our five built-in spaces, defined to OCIO through its built-in transforms (ACES AP0/AP1 to
  // CIE-XYZ-D65 with Bradford adaptation, AP1 to linear Rec.709) and, for Rec.2020 and P3-D65
  // which OCIO 2.1 has no linear built-in for, matrices from their published primaries.
  static SpaceLibrary builtin();
  // A studio config: spaces are its colour-space names; `xyz_space` names its CIE XYZ (D65)
  // space (default: the role cie_xyz_d65_interchange, else a space called CIE-XYZ-D65).
  static SpaceLibrary from_config(const std::string& config_path,
                                  const std::string& xyz_space = "");

  // The space's native matrices, white and reference illuminant (linear spaces only). A config's
  // conversion to its CIE XYZ D65 space includes the adaptation of the space's white to D65, so the
  // white is found in this order: `white` if given (the matrix is then Bradford-adapted from D65
  // back to it); the built-in space whose matrix to XYZ D65 the config's equals
  // (kBuiltinMatchTolerance per entry), whose primaries, white and illuminant it takes; otherwise
  // D65, the white of the config's XYZ space.
  RgbSpace space(const std::string& name,
                 const std::optional<SpaceWhite>& white = std::nullopt) const;
  // The built-in space whose RGB → CIE XYZ D65 matrix (through OCIO's built-in transforms) equals
  // `rgb_to_xyz_d65` within kBuiltinMatchTolerance per entry.
  static std::optional<std::string> matching_builtin(const Mat3& rgb_to_xyz_d65);
  // RGB in a space of this library → RGB in one of our built-in spaces (through CIE XYZ D65).
  Mat3 conversion_to_builtin(const std::string& from, const std::string& builtin) const;
  // RGB in `from` → RGB in `to`. Throws InputError if the conversion is not a pure matrix.
  Mat3 conversion(const std::string& from, const std::string& to) const;
  std::vector<std::string> names() const;
  // The first of names() whose primaries and white are within `tolerance` (in x and y) of `c`;
  // empty if none (spaces that are not linear matrices are skipped).
  std::string space_with_chromaticities(const SpaceChromaticities& c, double tolerance) const;
  bool is_builtin() const { return config_path_.empty(); }
  const std::string& config_path() const { return config_path_; }

 private:
  friend class DisplayTransform;
  struct Impl;
  std::shared_ptr<const Impl> impl_;
  std::string config_path_;
};

// The built-in displays and views (used without an OCIO config): display "sRGB"; views
// "ACES 1.0 - SDR Video" (OCIO's built-in ACES RRT + sRGB 100-nit dim-surround ODT, the default)
// and "Un-tone-mapped" (linear Rec.709 clipped to [0, 1] and sRGB-encoded).
inline constexpr const char* kBuiltinDisplay = "sRGB";
inline constexpr const char* kAcesSdrView = "ACES 1.0 - SDR Video";
inline constexpr const char* kUntonemappedView = "Un-tone-mapped";

// Which OpenColorIO display and view turn scene-linear values into pictures for eyes, and an
// exposure (stops) applied in scene-linear before the view. Without a config, an empty display or
// view is the built-in display sRGB or `builtin_view` (one of the built-in views above). With a
// config, an empty one is the config's default display, or its default view of the display;
// except that with `builtin_unless_named` (the reflectance view) neither named means the built-in
// display and `builtin_view`.
struct ViewSettings {
  std::string display, view;
  double exposure_ev = 0;
  std::string builtin_view = kAcesSdrView;
  bool builtin_unless_named = false;
};

// A display/view transform from a working space of a SpaceLibrary, built once (OCIO processor)
// and applied to many images. With the built-in library only the built-in display and views
// exist; with a config, a display and view it defines (OCIO DisplayViewTransform from the
// working space), its defaults for those not given (ViewSettings). InputError for an unknown one.
class DisplayTransform {
 public:
  DisplayTransform(const SpaceLibrary& spaces, const std::string& working_space,
                   const ViewSettings& settings);
  // Working-space RGB (3 floats per pixel) → display-encoded values in [0, 1], in place.
  void apply(std::vector<float>& rgb) const;
  // "display sRGB, view ACES 1.0 - SDR Video (OpenColorIO built-in), exposure +0 EV".
  const std::string& description() const { return description_; }
  // "display sRGB, view ACES 1.0 - SDR Video".
  const std::string& display_and_view() const { return display_and_view_; }

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
  std::string display_and_view_, description_;
};

}  // namespace fl::color
