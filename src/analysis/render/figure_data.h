#pragma once
// The numbers behind the figures, computed here so that draw/figures.h only draws: ground truth
// and model curves with their ΔE2000, colour-strip samples, and display codes for sphere renders.
// Display codes: reflectance colours through the context's OCIO reflectance view
// (Context::reflectance_display), renders through a given view; 8-bit codes round(255·v).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/pipeline/context.h"
#include "analysis/render/render.h"
#include "color/ocio.h"
#include "fresnel/registered_models.h"

namespace fl::analysis {

struct FigureModel {
  fresnel::Model model;
  std::vector<double> params;  // flat parameter vector (registered_models.h)
};

struct FigureRequest {
  std::string material;        // shown in titles
  std::string parameter_kind;  // "derived" or "fitted", shown in titles
  const spectral::ComplexIorSpectrum* ior = nullptr;
  std::vector<FigureModel> models;
};

// What a figure's title and subtitle state.
struct FigureCaption {
  std::string material, parameter_kind, space, illuminant;
  std::string view;  // the display view the colours went through (DisplayTransform::description)
};

struct ModelCurveData {
  std::string name;
  std::vector<color::Rgb> rgb;  // working-space reflectance at the context's angles
  std::vector<double> de2000;   // against the ground truth, per angle
  double rms_de2000 = 0;        // over the context's angles (curve_error)
};

struct CurveData {
  FigureCaption caption;
  std::vector<double> angles_deg;
  std::vector<color::Rgb> truth;  // spectral ground truth at angles_deg
  std::vector<ModelCurveData> models;
};

// The ground truth and each model's curve at the context's angles.
CurveData curve_data(const Context& ctx, const FigureRequest& in);

// An angular range sampled at `samples` column centres θ_i = θ0 + (θ1 − θ0)·(i + ½)/samples.
struct StripSpan {
  double theta0_deg = 0, theta1_deg = 90;
  int samples = 0;
};
// 0°–90° at 6 samples per degree, and a zoom on 80°–90° at 30 per degree.
std::vector<StripSpan> default_strip_spans();

struct StripRow {
  std::string label;
  std::optional<double> rms_de2000;  // none for the ground truth row
  std::vector<std::uint8_t> srgb;    // display codes, 3 per sample, spans in order
  std::vector<double> de2000;        // per sample against the truth (empty for the truth row)
};

// The ΔE2000 a strip's error row shows at the top of its colour scale (larger values saturate):
// twice the conventional just-noticeable difference of 1, so that a 0.3 difference is 15 % up the
// scale and a visible difference sits in its middle.
inline constexpr double kStripDe2000Scale = 2.0;

struct StripData {
  FigureCaption caption;
  std::vector<StripSpan> spans;
  std::vector<StripRow> rows;  // ground truth, then each model
};

StripData strip_data(const Context& ctx, const FigureRequest& in,
                     const std::vector<StripSpan>& spans = default_strip_spans());

// Working-space reflectance RGB (3 floats per pixel) → 8-bit display codes through the context's
// reflectance view (Context::reflectance_display).
std::vector<std::uint8_t> display_encode(const Context& ctx, const std::vector<float>& working_rgb);

// What a gallery card shows of a material: the ground truth's display codes at `samples` angles
// θ_i = 90°·i/(samples − 1) (a colour strip), and at 0° (F0) and θ = arccos(1/7) ≈ 81.79° (F82).
struct MaterialSwatches {
  std::vector<std::uint8_t> strip;  // 3 codes per angle
  std::array<std::uint8_t, 3> f0{}, f82{};
};
MaterialSwatches material_swatches(const Context& ctx, const spectral::ComplexIorSpectrum& ior,
                                   int samples = 19);

// What a render's picture shows where the render has no light of its own. Dark: a dark grey
// (0.02) behind the sphere, for metals, whose reflection is all there is. ReflectionOnMidGrey:
// for dielectrics, whose renders hold the reflection only (no transmission), the reflection added
// over a mid grey (0.18, behind and under the sphere) so that it reads as a reflection rather than
// as a black ball.
enum class Backdrop { Dark, ReflectionOnMidGrey };
inline constexpr float kDarkBackdrop = 0.02f, kMidGreyBackdrop = 0.18f;
Backdrop backdrop_for(spectral::MaterialClass c);
// Whether pictures of class c show the reflection only (on the ReflectionOnMidGrey backdrop).
bool reflection_only(spectral::MaterialClass c);
// The caption a picture on the ReflectionOnMidGrey backdrop carries.
inline constexpr const char* kReflectionOnlyNote =
    "reflection only (no transmission), added over mid grey 0.18";

// A render on `backdrop` passed through `view` (an OCIO display and view), as display-encoded
// floats in [0, 1] (3 per pixel, the render's layout), before any rounding to codes.
std::vector<float> sphere_display_values(const color::DisplayTransform& view,
                                         const SphereImage& img,
                                         Backdrop backdrop = Backdrop::Dark);
// sphere_display_values as 8-bit codes.
std::vector<std::uint8_t> sphere_display(const color::DisplayTransform& view,
                                         const SphereImage& img,
                                         Backdrop backdrop = Backdrop::Dark);

}  // namespace fl::analysis
