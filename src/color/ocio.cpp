#include "color/ocio.h"

#include <OpenColorIO/OpenColorIO.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "color/colorimetry.h"
#include "color/ocio_checks.h"
#include "spectral/text_file.h"
#include "util/errors.h"

namespace OCIO = OCIO_NAMESPACE;

namespace fl::color {

struct SpaceLibrary::Impl {
  OCIO::ConstConfigRcPtr config;
  std::string xyz_space;  // user config only
};

namespace {

OCIO::TransformRcPtr ocio_builtin(const char* style,
                                  OCIO::TransformDirection dir = OCIO::TRANSFORM_DIR_FORWARD) {
  auto t = OCIO::BuiltinTransform::Create();
  t->setStyle(style);
  t->setDirection(dir);
  return t;
}

OCIO::TransformRcPtr matrix_transform(const Mat3& m, OCIO::TransformDirection dir) {
  auto t = OCIO::MatrixTransform::Create();
  const double m44[16] = {m(0, 0), m(0, 1), m(0, 2), 0, m(1, 0), m(1, 1), m(1, 2), 0,
                          m(2, 0), m(2, 1), m(2, 2), 0, 0,       0,       0,       1};
  t->setMatrix(m44);
  t->setDirection(dir);
  return t;
}

// Our built-in space → CIE XYZ with a D65 white (OCIO's interchange convention).
OCIO::TransformRcPtr builtin_to_xyz_d65(const std::string& name, OCIO::TransformDirection dir) {
  if (name == "acescg") return ocio_builtin("UTILITY - ACES-AP1_to_CIE-XYZ-D65_BFD", dir);
  if (name == "aces2065-1") return ocio_builtin("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD", dir);
  if (name == "lin_rec709") {
    // Rec.709 → AP1 → XYZ-D65: the two Bradford adaptations (D65 → ACES → D65) cancel exactly.
    auto g = OCIO::GroupTransform::Create();
    g->appendTransform(
        ocio_builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", OCIO::TRANSFORM_DIR_INVERSE));
    g->appendTransform(ocio_builtin("UTILITY - ACES-AP1_to_CIE-XYZ-D65_BFD"));
    g->setDirection(dir);
    return g;
  }
  if (name == "lin_rec2020" || name == "lin_p3d65")
    return matrix_transform(builtin_space(name).rgb_to_xyz, dir);
  builtin_space(name);  // throws the helpful error
  return nullptr;
}

// Multiplies out a processor made only of matrix ops, in double.
Mat3 processor_matrix(const OCIO::ConstProcessorRcPtr& proc, const std::string& what) {
  const auto group = proc->createGroupTransform();
  Mat3 total;
  for (int i = 0; i < group->getNumTransforms(); ++i) {
    const auto t = group->getTransform(i);
    const auto mt = OCIO::DynamicPtrCast<const OCIO::MatrixTransform>(t);
    if (!mt)
      throw InputError(
          fmt::format("{} is not a linear (matrix-only) conversion in OpenColorIO", what));
    double m44[16], off[4];
    mt->getMatrix(m44);
    mt->getOffset(off);
    if (off[0] != 0 || off[1] != 0 || off[2] != 0)
      throw InputError(fmt::format("{} has an offset: not a linear colour space", what));
    Mat3 m{{m44[0], m44[1], m44[2], m44[4], m44[5], m44[6], m44[8], m44[9], m44[10]}};
    if (mt->getDirection() == OCIO::TRANSFORM_DIR_INVERSE) m = m.inverse();
    total = m * total;
  }
  return total;
}

}  // namespace

SpaceLibrary SpaceLibrary::builtin() {
  SpaceLibrary lib;
  auto impl = std::make_shared<Impl>();
  impl->config = OCIO::Config::CreateRaw();
  lib.impl_ = impl;
  return lib;
}

// The file is checked as every input is (a regular file of bounded size), then the config
// (ocio_checks.h: roles naming defined spaces, OCIO's validation, the XYZ space not data); each
// space is checked when used (defined, not data, a matrix from and to the others).
SpaceLibrary SpaceLibrary::from_config(const std::string& path, const std::string& xyz_space) {
  SpaceLibrary lib;
  auto impl = std::make_shared<Impl>();
  spectral::check_input_file(path);
  try {
    impl->config = OCIO::Config::CreateFromFile(path.c_str());
  } catch (const OCIO::Exception& e) {
    throw InputError(path, 0, std::string("cannot load OCIO config: ") + e.what());
  }
  validate_config(*impl->config, path);
  std::string xyz = xyz_space;
  if (xyz.empty()) {
    if (impl->config->hasRole("cie_xyz_d65_interchange"))
      xyz = impl->config->getColorSpace("cie_xyz_d65_interchange")->getName();
    else if (impl->config->getColorSpace("CIE-XYZ-D65"))
      xyz = "CIE-XYZ-D65";
    else
      throw InputError(path, 0,
                       "the config has no CIE XYZ D65 space (role cie_xyz_d65_interchange or a "
                       "space CIE-XYZ-D65); name one with --ocio-xyz");
  }
  require_colour_space(*impl->config, path, xyz, "the CIE XYZ D65 space");
  impl->xyz_space = xyz;
  lib.impl_ = impl;
  lib.config_path_ = path;
  return lib;
}

std::vector<std::string> SpaceLibrary::names() const {
  if (is_builtin()) return builtin_space_names();
  std::vector<std::string> out;
  for (int i = 0; i < impl_->config->getNumColorSpaces(); ++i)
    out.emplace_back(impl_->config->getColorSpaceNameByIndex(i));
  return out;
}

std::string SpaceLibrary::space_with_chromaticities(const SpaceChromaticities& c,
                                                    double tolerance) const {
  for (const auto& n : names()) {
    try {
      if (chromaticity_distance(chromaticities_of(space(n)), c) <= tolerance) return n;
    } catch (const InputError&) {
      // not a linear space: it cannot be the one
    }
  }
  return {};
}

Mat3 SpaceLibrary::conversion(const std::string& from, const std::string& to) const {
  const std::string what = fmt::format("conversion {} -> {}", from, to);
  try {
    if (is_builtin()) {
      auto g = OCIO::GroupTransform::Create();
      g->appendTransform(builtin_to_xyz_d65(from, OCIO::TRANSFORM_DIR_FORWARD));
      g->appendTransform(builtin_to_xyz_d65(to, OCIO::TRANSFORM_DIR_INVERSE));
      return processor_matrix(impl_->config->getProcessor(g), what);
    }
    for (const auto& n : {from, to})
      require_colour_space(*impl_->config, config_path_, n, "converted as a colour");
    try {
      return processor_matrix(impl_->config->getProcessor(from.c_str(), to.c_str()), what);
    } catch (const InputError& e) {
      throw InputError(config_path_, 0, e.what());
    }
  } catch (const OCIO::Exception& e) {
    throw InputError(fmt::format("OpenColorIO cannot build the {}: {}", what, e.what()));
  }
}

std::optional<std::string> SpaceLibrary::matching_builtin(const Mat3& rgb_to_xyz_d65) {
  const auto raw = OCIO::Config::CreateRaw();
  for (const auto& b : builtin_space_names()) {
    const Mat3 m =
        processor_matrix(raw->getProcessor(builtin_to_xyz_d65(b, OCIO::TRANSFORM_DIR_FORWARD)), b);
    double diff = 0;
    for (int i = 0; i < 9; ++i) diff = std::max(diff, std::abs(m.m[i] - rgb_to_xyz_d65.m[i]));
    if (diff <= kBuiltinMatchTolerance) return b;
  }
  return std::nullopt;
}

Mat3 SpaceLibrary::conversion_to_builtin(const std::string& from,
                                         const std::string& builtin) const {
  if (is_builtin()) return conversion(from, builtin);
  const auto raw = OCIO::Config::CreateRaw();
  const Mat3 from_xyz =
      processor_matrix(raw->getProcessor(builtin_to_xyz_d65(builtin, OCIO::TRANSFORM_DIR_INVERSE)),
                       "CIE XYZ D65 -> " + builtin);
  return from_xyz * conversion(from, impl_->xyz_space);
}

RgbSpace SpaceLibrary::space(const std::string& name,
                             const std::optional<SpaceWhite>& white) const {
  if (is_builtin()) return builtin_space(name);
  const Mat3 to_xyz_d65 = conversion(name, impl_->xyz_space);
  RgbSpace s;
  const auto builtin = white ? std::nullopt : matching_builtin(to_xyz_d65);
  if (builtin) {
    s = builtin_space(*builtin);
    s.white_source = fmt::format("white {} of built-in {}, whose matrix the config's equals",
                                 s.reference_illuminant, *builtin);
  } else {
    const Xyz d65 = to_xyz_d65 * Rgb{1, 1, 1};
    s.white = white ? white->white : d65;
    s.rgb_to_xyz = adaptation_matrix(Adaptation::Bradford, d65, s.white) * to_xyz_d65;
    s.reference_illuminant = white ? white->illuminant : "D65";
    s.white_source = white ? white->source : "white D65 of the config's CIE XYZ D65 space";
  }
  s.name = name;
  s.description = fmt::format("'{}' from OCIO config {}", name, config_path_);
  try {
    s.xyz_to_rgb = s.rgb_to_xyz.inverse();
  } catch (const std::domain_error&) {
    throw InputError(config_path_, 0, fmt::format("colour space '{}' has a singular matrix", name));
  }
  return s;
}

struct DisplayTransform::Impl {
  OCIO::ConstCPUProcessorRcPtr cpu;
};

namespace {

bool view_exists(const OCIO::Config& config, const std::string& display, const std::string& view) {
  for (int i = 0; i < config.getNumViews(display.c_str()); ++i)
    if (view == config.getView(display.c_str(), i)) return true;
  return false;
}

// Clamps every channel to [0, 1].
OCIO::TransformRcPtr clip_unit() {
  auto r = OCIO::RangeTransform::Create();
  r->setStyle(OCIO::RANGE_CLAMP);
  r->setMinInValue(0);
  r->setMinOutValue(0);
  r->setMaxInValue(1);
  r->setMaxOutValue(1);
  return r;
}

// Working space → ACES2065-1 (a matrix through OCIO), then the built-in view and sRGB display.
OCIO::GroupTransformRcPtr builtin_view(const SpaceLibrary& spaces, const std::string& working,
                                       const std::string& view) {
  auto g = OCIO::GroupTransform::Create();
  if (view == kAcesSdrView) {
    g->appendTransform(matrix_transform(spaces.conversion_to_builtin(working, "aces2065-1"),
                                        OCIO::TRANSFORM_DIR_FORWARD));
    g->appendTransform(ocio_builtin("ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0"));
  } else {
    g->appendTransform(matrix_transform(spaces.conversion_to_builtin(working, "lin_rec709"),
                                        OCIO::TRANSFORM_DIR_FORWARD));
    g->appendTransform(clip_unit());
    g->appendTransform(builtin_to_xyz_d65("lin_rec709", OCIO::TRANSFORM_DIR_FORWARD));
  }
  g->appendTransform(ocio_builtin("DISPLAY - CIE-XYZ-D65_to_sRGB"));
  return g;
}

}  // namespace

DisplayTransform::DisplayTransform(const SpaceLibrary& spaces, const std::string& working,
                                   const ViewSettings& vs) {
  if (!std::isfinite(vs.exposure_ev) || std::abs(vs.exposure_ev) > 32)
    throw InputError("--exposure must be between -32 and 32 stops");
  auto impl = std::make_shared<Impl>();
  // Without a config the built-in display and view; with a config, a missing one is the config's
  // default display, or its default view of the display (ViewSettings::builtin_unless_named aside).
  const bool builtin =
      spaces.is_builtin() || (vs.builtin_unless_named && vs.display.empty() && vs.view.empty());
  const auto* config = spaces.impl_->config.get();
  std::string display = vs.display, view = vs.view;
  if (display.empty()) display = builtin ? kBuiltinDisplay : config->getDefaultDisplay();
  if (view.empty()) view = builtin ? vs.builtin_view : config->getDefaultView(display.c_str());
  auto g = OCIO::GroupTransform::Create();
  auto exposure = OCIO::MatrixTransform::Create();
  const double k = std::exp2(vs.exposure_ev);
  const double m44[16] = {k, 0, 0, 0, 0, k, 0, 0, 0, 0, k, 0, 0, 0, 0, 1};
  exposure->setMatrix(m44);
  g->appendTransform(exposure);
  std::string source = "OpenColorIO built-in";
  try {
    if (builtin) {
      if (display != kBuiltinDisplay || (view != kAcesSdrView && view != kUntonemappedView))
        throw InputError(fmt::format(
            "unknown display/view '{}' / '{}': without an OCIO config the display is {} and the "
            "view {} or {}",
            display, view, kBuiltinDisplay, kAcesSdrView, kUntonemappedView));
      g->appendTransform(builtin_view(spaces, working, view));
    } else {
      if (!view_exists(*config, display, view))
        throw InputError(
            spaces.config_path(), 0,
            fmt::format("the config has no display '{}' with view '{}'", display, view));
      auto dv = OCIO::DisplayViewTransform::Create();
      dv->setSrc(working.c_str());
      dv->setDisplay(display.c_str());
      dv->setView(view.c_str());
      g->appendTransform(dv);
      source = "OCIO config " + spaces.config_path();
    }
    impl->cpu = spaces.impl_->config->getProcessor(g)->getDefaultCPUProcessor();
  } catch (const OCIO::Exception& e) {
    throw InputError(fmt::format("OpenColorIO cannot build display '{}', view '{}': {}", display,
                                 view, e.what()));
  }
  impl_ = impl;
  display_and_view_ = fmt::format("display {}, view {}", display, view);
  description_ =
      fmt::format("{} ({}), exposure {:+g} EV", display_and_view_, source, vs.exposure_ev);
}

void DisplayTransform::apply(std::vector<float>& rgb) const {
  OCIO::PackedImageDesc img(rgb.data(), static_cast<long>(rgb.size() / 3), 1, 3);
  impl_->cpu->apply(img);
  for (auto& v : rgb) v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
}

}  // namespace fl::color
