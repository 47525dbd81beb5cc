#pragma once
// The figures as Drawings (draw.h), from data computed in analysis/figure_data.h: colour strips,
// reflectance / ΔE2000 curves, and the ΔE2000 heat map of a sphere render.
#include <string>
#include <vector>

#include "analysis/render/figure_data.h"
#include "report/draw.h"

namespace fl::report {

// Stacked strips, one row per StripData row (ground truth, then each model), one pixel column per
// sample of each span, spans side by side; the RMS ΔE2000 of each model on the right.
Drawing strip_drawing(const analysis::StripData& d);

// Where strip_drawing paints a sample: the top-left pixel of its column (kStripRowHeight tall).
constexpr int kStripRowHeight = 30;
Point strip_cell(const analysis::StripData& d, size_t row, size_t span, int sample);

// R, G, B reflectance against angle (ground truth solid, models dashed) and ΔE2000 against angle.
Drawing curves_drawing(const analysis::CurveData& d);

// ΔE2000 per pixel (row-major, NaN: no surface) as a heat map on the inferno ramp, with a colour
// bar from 0 to the nice ceiling of the largest ΔE (at least 1), its ticks labelled.
Drawing heatmap_drawing(const std::vector<double>& de, int width, int height, const std::string& title);

// The map's pixels are drawn unscaled with their top-left corner at (0, kHeatmapImageTop); the
// colour bar's top pixel row shows the scale's top, its bottom row 0.
constexpr int kHeatmapImageTop = 34;
struct ColourBar {
  int x = 0, y = 0, width = 0, height = 0;
};
ColourBar heatmap_colour_bar(int width, int height);

// The ramp: five control points of matplotlib's "inferno" (van der Walt & Smith 2015, CC0),
// sRGB-encoded, interpolated linearly between them; t is clamped to [0, 1].
Rgb8 inferno(double t);

}  // namespace fl::report
