#pragma once
// The colorimetric setting of a run (docs/conventions.md, "Colorimetry") and the ground-truth
// machinery built on it.
#include <optional>
#include <string>
#include <vector>

#include "color/colorimetry.h"
#include "color/lab.h"
#include "color/ocio.h"
#include "spectral/material.h"

namespace fl::analysis {

struct Settings {
  std::string space = "acescg";
  std::string illuminant;  // empty: the working space's reference white illuminant

  std::string adaptation = "bradford";
  int angles = 91;
  double step_nm = 5.0;
  double eta_outside = 1.0;  // real index of the medium the surface is seen from
  std::string ocio_config;   // empty: built-in spaces
  std::string ocio_xyz;      // the config's CIE XYZ D65 space (empty: role / default name)
  std::string
      ocio_white;  // a config space's white: ACES or an illuminant name (empty: from the config)
  // The display and view renders (scene-linear radiance) go through, and the view of reflectance
  // colours (strips, swatches: already display-referred, 1 is a white surface), by default the
  // built-in Un-tone-mapped view: a tone-mapping view's shoulder would desaturate them.
  color::ViewSettings view;
  std::string reflectance_view;
  spectral::DataPaths paths;
};

// Precomputed colour pipeline: reflectance spectrum → working-space RGB is linear, RGB =
// Σ R(λ)·w(λ) with w = M_xyz→rgb · CAT(illuminant white → space white) · (S x̄, S ȳ, S z̄)/Σ S ȳ.
class Context {
 public:
  explicit Context(const Settings& settings);

  // The settings as resolved: `illuminant` is never empty (the space's reference white by default).
  const Settings& settings() const { return settings_; }
  const spectral::SpectralGrid& grid() const { return grid_; }
  const color::RgbSpace& space() const { return space_; }
  const color::SpaceLibrary& spaces() const { return spaces_; }
  // settings().view from the working space: what renders, their flips and sheets go through.
  const color::DisplayTransform& display() const { return display_; }
  // settings().view's display with reflectance_view (no exposure): what strips and swatches of
  // reflectance go through.
  const color::DisplayTransform& reflectance_display() const { return reflectance_display_; }
  const std::vector<color::Rgb>& rgb_weights() const { return rgb_weights_; }
  // Per grid wavelength S·ȳ / Σ S·ȳ: its share of a white surface's luminance (sums to 1).
  const std::vector<double>& luminance_weights() const { return luminance_weights_; }

  // Incidence angles θ_i = 90°·i/(N − 1); cos is exactly 0 at 90°.
  const std::vector<double>& angles_deg() const { return angles_deg_; }
  const std::vector<double>& cos_thetas() const { return cos_thetas_; }
  // Render weights ∝ sinθ·cosθ (the share of a sphere's image that sees θ), summing to 1.
  const std::vector<double>& render_weights() const { return render_weights_; }

  color::Rgb spectrum_to_rgb(const std::vector<double>& values) const;

  template <class T>
  color::LabT<T> rgb_to_lab(const color::RgbT<T>& rgb) const {
    return color::LabConverter{space_.rgb_to_xyz, space_.white}(rgb);
  }

 private:
  Settings settings_;
  spectral::SpectralGrid grid_;
  color::SpaceLibrary spaces_;
  color::RgbSpace space_;
  color::DisplayTransform display_, reflectance_display_;
  color::Xyz illuminant_white_;
  std::vector<color::Rgb> rgb_weights_;
  std::vector<double> luminance_weights_;
  std::vector<double> angles_deg_, cos_thetas_, render_weights_;
};

// How much of the visible range the data measures rather than holds at its nearest value, each
// grid wavelength weighted by its share of a white surface's luminance (Context::luminance_weights,
// the illuminant × ȳ). Data without any k (a lossless material) counts k as given everywhere.
struct Coverage {
  double n = 1.0;     // weighted fraction where n is measured
  double k = 1.0;     // where k is measured; NaN when the data has no k at all
  double both = 1.0;  // where n and k are both measured (k counted everywhere without k data)
  bool extrapolated = false;  // some grid wavelength holds a nearest value (any weight)
  std::string uncovered;      // "n and k data does not cover 360-600 nm" (empty: nothing held)
};
Coverage coverage_of(const Context& ctx, const spectral::SampledIor& s);

// What a consensus material rests on (analysis/consensus): its bulk pages and their spread around
// it, the ΔE2000 of their F0 and F82 from the consensus' and each channel's range over them.
struct ConsensusBasis {
  int pages = 0;  // 1: a single page, not a consensus
  double f0_median = 0, f0_max = 0, f82_median = 0, f82_max = 0;
  color::Rgb f0_lo, f0_hi, f82_lo, f82_hi;
};

struct LoadedMaterial {
  spectral::Material material;
  spectral::ComplexIorSpectrum ior;
  std::vector<std::string> warnings;  // the reader's and the sampling's, one line each
  Coverage coverage;
  std::optional<ConsensusBasis> consensus;  // a consensus material's basis
  std::string resolved;  // why a short name ("gold") gave this material (analysis/consensus)
};
LoadedMaterial load_material(const Context& ctx, spectral::Material m);
std::vector<LoadedMaterial> load_catalog(const Context& ctx);

// Spectral ground truth: per angle, the reflectance spectrum at cosθ for the index relative to
// the outside medium eta_outside, pushed through the colour pipeline.
color::Rgb ground_truth_rgb(const Context& ctx, const spectral::ComplexIorSpectrum& ior,
                            double cos_theta, double eta_outside);
std::vector<color::Rgb> ground_truth_curve(const Context& ctx,
                                           const spectral::ComplexIorSpectrum& ior,
                                           double eta_outside);

struct CurveError {
  double rms = 0, mean = 0, max = 0, rms_weighted = 0;
};
// ΔE2000 per angle between two RGB curves in the working space.
std::vector<double> de2000_per_angle(const Context& ctx, const std::vector<color::Rgb>& a,
                                     const std::vector<color::Rgb>& b);
// The same with `a` already in CIELAB: ΔE2000 per pair (an angle's, a shading point's) in SIMD
// lanes (color::ciede2000_batch).
std::vector<double> de2000_per_angle(const Context& ctx, const std::vector<color::Lab>& lab_a,
                                     const std::vector<color::Rgb>& b);
CurveError curve_error(const Context& ctx, const std::vector<color::Rgb>& truth,
                       const std::vector<color::Rgb>& approx);
// Each colour of a curve in CIELAB (rgb_to_lab).
std::vector<color::Lab> lab_curve(const Context& ctx, const std::vector<color::Rgb>& rgb);
// The same with the truth already in CIELAB (rgb_to_lab at each angle), for a truth measured
// against many curves.
CurveError curve_error(const Context& ctx, const std::vector<color::Lab>& truth_lab,
                       const std::vector<color::Rgb>& approx);

}  // namespace fl::analysis
