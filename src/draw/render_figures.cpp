// The figures of renders: ΔE2000 heatmaps with their colour bar, and contact sheets of spheres.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "draw/figures.h"
#include "draw/inferno_table.h"
#include "draw/plot.h"

namespace fl::draw {

io::Rgb8 inferno(double t) {
  const double x = std::clamp(t, 0.0, 1.0) * (kInfernoEntries - 1);
  const int i = std::min(kInfernoEntries - 2, static_cast<int>(x));
  const double f = x - i;
  const auto ch = [&](int c) {
    const double v = kInferno[i][c] + (kInferno[i + 1][c] - kInferno[i][c]) * f;
    return static_cast<std::uint8_t>(std::lround(255.0 * v));
  };
  return {ch(0), ch(1), ch(2)};
}

namespace {

// Heat map layout (pixels): title band, then the image with the colour bar to its right.
constexpr io::Rgb8 kNoSurface{235, 235, 235};
constexpr int kHeatTop = kHeatmapImageTop, kHeatBarGap = 16, kHeatBarW = 18, kHeatRight = 110,
              kHeatMinBar = 120;

void add_colour_bar(Drawing& dr, const ColourBar& bar, double scale, double de_max) {
  io::Image8 ramp(bar.width, bar.height);
  for (int y = 0; y < bar.height; ++y) {
    const io::Rgb8 c =
        inferno(bar.height > 1 ? 1.0 - static_cast<double>(y) / (bar.height - 1) : 1.0);
    for (int x = 0; x < bar.width; ++x) ramp.set(x, y, c);
  }
  dr.add(Picture{bar.x, bar.y, std::move(ramp)});
  const auto ticks = nice_ticks(0, scale, 4);
  const int decimals = tick_decimals(ticks);
  for (double t : ticks) {
    const double y = bar.y + std::round((1.0 - t / scale) * (bar.height - 1));
    dr.add(Rect{double(bar.x + bar.width), y, 4, 1, kInk});
    dr.add(Text{double(bar.x + bar.width + 7), y + 4.5, tick_label(t, decimals), 11, kInk});
  }
  dr.add(Text{double(bar.x), double(bar.y + bar.height + 16), "ΔE2000", 11, kInk});
  dr.add(Text{double(bar.x), double(bar.y - 8), fmt::format("max {:.2f}", de_max), 10, kGreyInk});
}

}  // namespace

ColourBar heatmap_colour_bar(int width, int height) {
  return {width + kHeatBarGap, kHeatTop + 16, kHeatBarW, std::max(height - 32, kHeatMinBar)};
}

double heatmap_scale(const std::vector<double>& de) {
  double de_max = 0;
  for (double v : de)
    if (std::isfinite(v)) de_max = std::max(de_max, v);
  return nice_ceiling(std::max(1.0, de_max));
}

io::Image8 heatmap_image(const std::vector<double>& de, int width, int height, double scale) {
  io::Image8 map(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double v = de[static_cast<size_t>(y) * width + x];
      map.set(x, y, std::isfinite(v) ? inferno(v / scale) : kNoSurface);
    }
  return map;
}

Drawing heatmap_drawing(const std::vector<double>& de, int width, int height,
                        const std::string& title, const LabelFont& font, double scale) {
  double de_max = 0;
  for (double v : de)
    if (std::isfinite(v)) de_max = std::max(de_max, v);
  if (!(scale > 0)) scale = heatmap_scale(de);
  const ColourBar bar = heatmap_colour_bar(width, height);
  Drawing dr;
  dr.width = std::max(width + kHeatRight,
                      static_cast<int>(std::ceil(8 + text_width_px(title, 13, font) + 8)));
  dr.height = std::max(kHeatTop + height, bar.y + bar.height + 24) + 8;
  dr.add(Text{8, 22, title, 13, kInk});
  dr.add(Picture{0, kHeatTop, heatmap_image(de, width, height, scale)});
  add_colour_bar(dr, bar, scale, de_max);
  return dr;
}

namespace {

// Contact sheet layout (pixels): title band, then one row per model with a label line above
// its tiles, tiles kSheetGap apart, the shared colour bar at the right.
constexpr int kSheetMargin = 16, kSheetTitle = 30, kSheetNoteLine = 18, kSheetNotes = 2,
              kSheetGap = 12, kSheetLabel = 22, kSheetRowGap = 18, kSheetBar = 110;
// Tiles narrower than this still get a column this wide, so that their labels stay legible; a
// label wider than its column is set smaller to fit (text_size_to_fit), down to kSheetMinLabelPt.
constexpr int kSheetMinColumn = 180;
constexpr double kSheetLabelPt = 12, kSheetMinLabelPt = 8;

int sheet_column(const ContactSheet& s) {
  return std::max(s.truth.width, kSheetMinColumn);
}

void add_sheet_row(Drawing& dr, const ContactSheet& s, size_t r, double scale,
                   const LabelFont& font) {
  const auto& row = s.rows[r];
  const int size = s.truth.width, top = sheet_row_top(s, r);
  const std::string labels[3] = {
      "ground truth (spectral)", row.label,
      fmt::format("ΔE2000: mean {:.2f}, max {:.2f}", row.mean_de2000, row.max_de2000)};
  for (int c = r == 0 ? 0 : 1; c < 3; ++c) {  // the truth once, in the first row
    const Point p = sheet_tile(s, r, c);
    dr.add(Text{
        p.x, double(top + 15), labels[c],
        text_size_to_fit(labels[c], kSheetLabelPt, kSheetMinLabelPt,
                         (c == 2 ? size + kHeatBarGap : sheet_column(s) + kSheetGap) - 4, font),
        c == 2 ? kGreyInk : kInk});
  }
  if (r == 0) dr.add(Picture{int(sheet_tile(s, r, 0).x), int(sheet_tile(s, r, 0).y), s.truth});
  dr.add(Picture{int(sheet_tile(s, r, 1).x), int(sheet_tile(s, r, 1).y), row.render});
  dr.add(Picture{int(sheet_tile(s, r, 2).x), int(sheet_tile(s, r, 2).y),
                 heatmap_image(row.de2000, size, size, scale)});
}

}  // namespace

int sheet_row_top(const ContactSheet& s, size_t row) {
  const int notes = static_cast<int>(std::max<size_t>(s.notes.size(), kSheetNotes));
  return kSheetTitle + 10 + notes * kSheetNoteLine + 8 +
         static_cast<int>(row) * (kSheetLabel + s.truth.height + kSheetRowGap);
}

Point sheet_tile(const ContactSheet& s, size_t row, int column) {
  return {double(kSheetMargin + column * (sheet_column(s) + kSheetGap)),
          double(sheet_row_top(s, row) + kSheetLabel)};
}

double contact_sheet_scale(const ContactSheet& s) {
  std::vector<double> all;
  for (const auto& row : s.rows) all.insert(all.end(), row.de2000.begin(), row.de2000.end());
  return heatmap_scale(all);
}

Drawing contact_sheet_drawing(const ContactSheet& s, const LabelFont& font) {
  if (s.rows.empty() || s.truth.width <= 0)
    throw std::invalid_argument("contact_sheet_drawing: no rows");
  double de_max = 0;
  for (const auto& row : s.rows) de_max = std::max(de_max, row.max_de2000);
  const double scale = contact_sheet_scale(s);
  const int size = s.truth.width;
  Drawing dr;
  double text_w = text_width_px(s.title, 17, font);
  for (const auto& line : s.notes) text_w = std::max(text_w, text_width_px(line, 12, font));
  dr.width =
      std::max(kSheetMargin + 2 * (sheet_column(s) + kSheetGap) + size + kSheetGap + kSheetBar,
               static_cast<int>(std::ceil(2 * kSheetMargin + text_w)));
  dr.height = sheet_row_top(s, s.rows.size()) + 8;
  dr.add(Text{double(kSheetMargin), double(kSheetTitle), s.title, 17, kInk});
  for (size_t i = 0; i < s.notes.size(); ++i)
    dr.add(Text{double(kSheetMargin), double(kSheetTitle + 22 + kSheetNoteLine * i), s.notes[i], 12,
                kGreyInk});
  for (size_t r = 0; r < s.rows.size(); ++r) add_sheet_row(dr, s, r, scale, font);
  const Point last = sheet_tile(s, 0, 2);
  const ColourBar bar{
      int(last.x) + size + kHeatBarGap, int(last.y) + 16, kHeatBarW,
      std::max(sheet_row_top(s, s.rows.size()) - kSheetRowGap - int(last.y) - 48, kHeatMinBar / 2)};
  add_colour_bar(dr, bar, scale, de_max);
  return dr;
}

}  // namespace fl::draw
