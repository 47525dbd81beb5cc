#pragma once
// Issue 7's figures: colour strips, reflectance / ΔE2000 curves, and the display images of sphere
// renders (the render itself is analysis/render.h). Colours are working-space RGB converted to
// linear Rec.709 with the SpaceLibrary's (OCIO) matrix, then sRGB display-encoded by OCIO
// (SpaceLibrary::encode_srgb_display).
#include <string>
#include <vector>

#include "analysis/context.h"
#include "analysis/render.h"
#include "fresnel/model_set.h"
#include "report/font.h"
#include "report/image.h"
#include "report/plot.h"

namespace fl::report {

struct ModelCurve {
  fresnel::Model model;
  std::vector<double> params;  // flat parameter vector (model_set.h)
};

struct FigureInput {
  std::string material;          // shown in titles
  std::string parameter_kind;    // "derived" or "fitted", shown in titles
  const spectral::ComplexIorSpectrum* ior = nullptr;
  std::vector<ModelCurve> models;
};

// Working-space RGB (3 floats per pixel) → 8-bit sRGB display values, through OCIO.
std::vector<std::uint8_t> display_encode(const analysis::Context& ctx, const std::vector<float>& working_rgb);

// Stacked strips, ground truth then each model: reflectance over 0°–90° and a zoom on 80°–90°,
// with the RMS ΔE2000 of each model over the context's angles.
Image8 strip_figure(const analysis::Context& ctx, const FigureInput& in, Font& font);

// R, G, B reflectance against angle (ground truth solid, models dashed) and ΔE2000 against angle.
Drawing curves_drawing(const analysis::Context& ctx, const FigureInput& in);

// A render composited over a dark grey background and display-encoded.
Image8 sphere_display(const analysis::Context& ctx, const analysis::SphereImage& img);

// ΔE2000 per pixel as a heat map (approximate matplotlib "inferno" ramp) with a colour bar; the
// scale's top is the nice ceiling of the largest ΔE (at least 1).
Image8 heatmap_figure(const std::vector<double>& de, int width, int height, const std::string& title, Font& font);

}  // namespace fl::report
