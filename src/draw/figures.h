#pragma once
// The figures as Drawings (drawing.h), from data computed in analysis/render/figure_data.h: colour
// strips, reflectance / ΔE2000 curves, and the ΔE2000 heat map of a sphere render.
#include <string>
#include <vector>

#include "analysis/render/figure_data.h"
#include "draw/drawing.h"

namespace fl::draw {

// Stacked strips, one row per StripData row (ground truth, then each model), one pixel column per
// sample of each span, spans side by side; the RMS ΔE2000 of each model on the right. Under each
// model's strip, its ΔE2000 against the truth per sample (inferno on 0 to kStripDe2000Scale,
// saturating above), with the scale's legend at the bottom.
Drawing strip_drawing(const analysis::StripData& d);

// Where strip_drawing paints a sample: the top-left pixel of its column (kStripRowHeight tall).
// Its ΔE2000 (model rows) is painted from kStripRowHeight + kStripDeOffset below it.
constexpr int kStripRowHeight = 30, kStripDeOffset = 2;
Point strip_cell(const analysis::StripData& d, size_t row, size_t span, int sample);

// R, G, B reflectance against angle (ground truth solid, models dashed) and ΔE2000 against angle.
Drawing curves_drawing(const analysis::CurveData& d);

// ΔE2000 per pixel (row-major, NaN: no surface) as a heat map on the inferno ramp, with a colour
// bar from 0 to `scale` (0: heatmap_scale(de)), its ticks labelled; sized for its title in `font`.
Drawing heatmap_drawing(const std::vector<double>& de, int width, int height,
                        const std::string& title, const LabelFont& font, double scale = 0);
// The nice ceiling of the largest finite ΔE (at least 1).
double heatmap_scale(const std::vector<double>& de);
// The map's pixels: inferno(ΔE / scale), light grey where there is no surface.
io::Image8 heatmap_image(const std::vector<double>& de, int width, int height, double scale);

// A flip comparison on one page: per model a row of the model's render and its ΔE2000 heat map,
// the ground truth render once, left of the first row (column 0), with one colour bar for every row
// (the scale is heatmap_scale over all rows, so rows compare).
struct ContactSheetRow {
  std::string label;  // the model (and its parameter set)
  io::Image8 render;  // display codes, the truth's size
  std::vector<double> de2000;
  double mean_de2000 = 0, max_de2000 = 0;
};
struct ContactSheet {
  std::string title;
  std::vector<std::string> notes;  // lines under the title
  io::Image8 truth;                // square
  std::vector<ContactSheetRow> rows;
};
// heatmap_scale over every row's ΔE2000: the one scale of the sheet and of its models' heat maps.
double contact_sheet_scale(const ContactSheet& s);
// Wide enough for its title and notes in `font`.
Drawing contact_sheet_drawing(const ContactSheet& sheet, const LabelFont& font);
// Where the sheet paints a tile (column 0 truth, 1 model, 2 heat map): its top-left pixel, and the
// top of a row's band (its label line).
Point sheet_tile(const ContactSheet& sheet, size_t row, int column);
int sheet_row_top(const ContactSheet& sheet, size_t row);

// The map's pixels are drawn unscaled with their top-left corner at (0, kHeatmapImageTop); the
// colour bar's top pixel row shows the scale's top, its bottom row 0.
constexpr int kHeatmapImageTop = 34;
struct ColourBar {
  int x = 0, y = 0, width = 0, height = 0;
};
ColourBar heatmap_colour_bar(int width, int height);

// The ramp: matplotlib's 256-entry "inferno" table (van der Walt & Smith 2015, matplotlib inferno,
// CC0; draw/inferno_table.h), sRGB-encoded, entry i at t = i / 255 and interpolated linearly
// between entries, as 8-bit codes; t is clamped to [0, 1].
io::Rgb8 inferno(double t);

}  // namespace fl::draw
