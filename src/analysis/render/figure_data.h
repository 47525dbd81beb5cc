#pragma once
// The numbers behind the figures, computed here so that draw/figures.h only draws: ground truth
// and model curves with their ΔE2000, colour-strip samples, and display codes for sphere renders.
// Display codes: working-space RGB → linear Rec.709 with the SpaceLibrary's (OCIO) matrix, then
// sRGB display-encoded by OCIO (SpaceLibrary::encode_srgb_display), as 8-bit codes round(255·v).
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
};

struct StripData {
  FigureCaption caption;
  std::vector<StripSpan> spans;
  std::vector<StripRow> rows;  // ground truth, then each model
};

StripData strip_data(const Context& ctx, const FigureRequest& in,
                     const std::vector<StripSpan>& spans = default_strip_spans());

// Working-space RGB (3 floats per pixel) → 8-bit sRGB display codes, through OCIO.
std::vector<std::uint8_t> display_encode(const Context& ctx, const std::vector<float>& working_rgb);

// What a gallery card shows of a material: the ground truth's display codes at `samples` angles
// θ_i = 90°·i/(samples − 1) (a colour strip), and at 0° (F0) and θ = arccos(1/7) ≈ 81.79° (F82).
struct MaterialSwatches {
  std::vector<std::uint8_t> strip;  // 3 codes per angle
  std::array<std::uint8_t, 3> f0{}, f82{};
};
MaterialSwatches material_swatches(const Context& ctx, const spectral::ComplexIorSpectrum& ior,
                                   int samples = 19);

// A render composited over a dark grey background and passed through `view` (an OCIO display and
// view), as 8-bit codes (3 per pixel, the render's layout).
std::vector<std::uint8_t> sphere_display(const color::DisplayTransform& view,
                                         const SphereImage& img);

}  // namespace fl::analysis
