#include "draw/figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "draw/inferno_table.h"
#include "draw/plot.h"

namespace fl::draw {
namespace {

// Strip layout (pixels): margin | row labels | spans, kStripGap apart | RMS ΔE2000 column | margin.
constexpr int kStripMargin = 16, kStripLabelW = 190, kStripGap = 36, kStripErrGap = 14,
              kStripErrW = 100;
constexpr int kStripTop = 84, kStripRowGap = 6;
// Under each model's strip, 2 px below it, its ΔE2000 row (kStripDeHeight tall); the legend's bar.
constexpr int kStripDeGap = kStripDeOffset, kStripDeHeight = 12, kStripLegendW = 240,
              kStripLegendH = 12;

std::vector<int> span_lefts(const analysis::StripData& d) {
  std::vector<int> xs;
  int x = kStripMargin + kStripLabelW;
  for (const auto& sp : d.spans) {
    xs.push_back(x);
    x += sp.samples + kStripGap;
  }
  xs.push_back(x - kStripGap);  // right end of the last span
  return xs;
}

// Row 0 (the truth) has no ΔE2000 row; every later row has one.
int strip_row_top(size_t row) {
  const int r = static_cast<int>(row);
  return kStripTop + r * (kStripRowHeight + kStripRowGap) +
         std::max(r - 1, 0) * (kStripDeGap + kStripDeHeight);
}

std::string degrees(double v) {
  return fmt::format("{:g}°", v);
}

// One span of one row: its sample colours, each stretched to a kStripRowHeight column.
io::Image8 strip_picture(const analysis::StripRow& row, size_t first_sample, int samples) {
  io::Image8 img(samples, kStripRowHeight);
  for (int x = 0; x < samples; ++x) {
    const std::uint8_t* p = &row.srgb[3 * (first_sample + x)];
    for (int y = 0; y < kStripRowHeight; ++y) img.set(x, y, {p[0], p[1], p[2]});
  }
  return img;
}

// One span of a model row's ΔE2000: inferno(ΔE / kStripDe2000Scale), saturating above the scale.
io::Image8 de_picture(const analysis::StripRow& row, size_t first_sample, int samples) {
  io::Image8 img(samples, kStripDeHeight);
  for (int x = 0; x < samples; ++x) {
    const io::Rgb8 c =
        inferno(std::min(row.de2000[first_sample + x] / analysis::kStripDe2000Scale, 1.0));
    for (int y = 0; y < kStripDeHeight; ++y) img.set(x, y, c);
  }
  return img;
}

void add_strip_rows(Drawing& dr, const analysis::StripData& d, const std::vector<int>& xs) {
  const int label_x = xs.front() - 10, err_x = xs.back() + kStripErrGap;
  for (size_t r = 0; r < d.rows.size(); ++r) {
    const auto& row = d.rows[r];
    const int top = strip_row_top(r), baseline = top + kStripRowHeight / 2 + 5;
    size_t first = 0;
    for (size_t s = 0; s < d.spans.size(); ++s) {
      dr.add(Picture{xs[s], top, strip_picture(row, first, d.spans[s].samples)});
      if (!row.de2000.empty())
        dr.add(Picture{xs[s], top + kStripRowHeight + kStripDeGap,
                       de_picture(row, first, d.spans[s].samples)});
      first += d.spans[s].samples;
    }
    dr.add(Text{double(label_x), double(baseline), row.label, 13, kInk, Align::Right, false});
    if (row.rms_de2000)
      dr.add(
          Text{double(err_x), double(baseline), fmt::format("{:.2f}", *row.rms_de2000), 13, kInk});
    else
      dr.add(Text{double(err_x), double(baseline), "—", 13, kGreyInk});
  }
}

// Ticks every label_step / 2 under a span, labelled every label_step.
void add_strip_ticks(Drawing& dr, const analysis::StripSpan& sp, int left, int bottom) {
  const double range = sp.theta1_deg - sp.theta0_deg;
  const double label_step = range >= 45 ? 10 : range >= 20 ? 5 : 2;
  for (double t = sp.theta0_deg; t <= sp.theta1_deg + 1e-9; t += 0.5 * label_step) {
    const double x =
        std::min(left + (t - sp.theta0_deg) / range * sp.samples, left + sp.samples - 0.5);
    const bool labelled = std::fabs(std::remainder(t, label_step)) < 1e-9;
    dr.add(Rect{std::floor(x), double(bottom + 2), 1, labelled ? 7.0 : 4.0, kInk});
    if (labelled)
      dr.add(Text{std::floor(x) + 0.5, double(bottom + 24), degrees(t), 12, kInk, Align::Center});
  }
}

// Under the first span, where each later span (a zoom) lies.
void add_zoom_marks(Drawing& dr, const analysis::StripData& d, const std::vector<int>& xs,
                    int bottom) {
  const auto& full = d.spans.front();
  const auto to_x = [&](double t) {
    return xs.front() + (t - full.theta0_deg) / (full.theta1_deg - full.theta0_deg) * full.samples;
  };
  for (size_t s = 1; s < d.spans.size(); ++s) {
    const double x0 = std::round(to_x(d.spans[s].theta0_deg)),
                 x1 = std::round(to_x(d.spans[s].theta1_deg));
    dr.add(Rect{x0, double(bottom + 32), x1 - x0, 2, kGreyInk});
    dr.add(Text{x0 - 6, double(bottom + 40), "zoomed", 11, kGreyInk, Align::Right});
  }
}

// The ΔE2000 rows' colour scale, left-aligned with the spans at `top`.
void add_de_legend(Drawing& dr, int left, int top) {
  io::Image8 bar(kStripLegendW, kStripLegendH);
  for (int x = 0; x < kStripLegendW; ++x)
    for (int y = 0; y < kStripLegendH; ++y) bar.set(x, y, inferno((x + 0.5) / kStripLegendW));
  dr.add(Text{double(left - 10), double(top + 10), "ΔE2000 row under each model", 12, kInk,
              Align::Right, false});
  dr.add(Picture{left, top, bar});
  const double scale = analysis::kStripDe2000Scale;
  for (int i = 0; i <= 4; ++i) {
    const double x = left + std::min(i / 4.0 * kStripLegendW, kStripLegendW - 1.0);
    dr.add(Rect{std::floor(x), double(top + kStripLegendH), 1, 4, kInk});
    dr.add(Text{std::floor(x) + 0.5, double(top + kStripLegendH + 16),
                fmt::format("{}{:g}", i == 4 ? "≥ " : "", scale * i / 4), 11, kInk, Align::Center});
  }
}

std::string span_heading(const analysis::StripSpan& sp, bool first) {
  return fmt::format("{} {}–{}", first ? "incidence angle" : "zoom", degrees(sp.theta0_deg),
                     degrees(sp.theta1_deg));
}

}  // namespace

Point strip_cell(const analysis::StripData& d, size_t row, size_t span, int sample) {
  return {double(span_lefts(d)[span] + sample), double(strip_row_top(row))};
}

Drawing strip_drawing(const analysis::StripData& d) {
  const auto xs = span_lefts(d);
  const int err_x = xs.back() + kStripErrGap;
  const int bottom = strip_row_top(d.rows.size()) - kStripRowGap;
  Drawing dr;
  dr.width = err_x + kStripErrW + kStripMargin;
  const bool has_de = d.rows.size() > 1;
  dr.height = bottom + (has_de ? 100 : 56);
  const auto& c = d.caption;
  dr.add(Text{kStripMargin, 26,
              fmt::format("{}: Fresnel reflectance, ground truth and models ({} parameters)",
                          c.material, c.parameter_kind),
              17, kInk});
  dr.add(Text{kStripMargin, 46,
              fmt::format("{} working space, {} illuminant; colours through OpenColorIO {}",
                          c.space, c.illuminant, c.view),
              12, kGreyInk});
  for (size_t s = 0; s < d.spans.size(); ++s)
    dr.add(Text{xs[s] + 0.5 * d.spans[s].samples, kStripTop - 10, span_heading(d.spans[s], s == 0),
                13, kInk, Align::Center});
  dr.add(Text{double(err_x), kStripTop - 10, "RMS ΔE2000", 13, kInk});
  add_strip_rows(dr, d, xs);
  for (size_t s = 0; s < d.spans.size(); ++s) add_strip_ticks(dr, d.spans[s], xs[s], bottom);
  if (!d.spans.empty()) add_zoom_marks(dr, d, xs, bottom);
  if (has_de) add_de_legend(dr, xs.front(), bottom + 58);
  return dr;
}

namespace {

const io::Rgb8 kChannel[3] = {{205, 40, 40}, {30, 150, 50}, {40, 80, 210}};
const io::Rgb8 kModel[] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                           {148, 103, 189}, {140, 86, 75},  {227, 119, 194}, {127, 127, 127}};
const Dash kDash[] = {{9, 5},  {2, 4},       {12, 4, 3, 4}, {5, 5},
                      {16, 5}, {3, 3, 3, 8}, {1, 3},        {7, 3, 1, 3}};
constexpr size_t kStyles = 8;
const std::vector<double> kAngleTicks{0, 10, 20, 30, 40, 50, 60, 70, 80, 90};

std::vector<double> channel(const std::vector<color::Rgb>& c, int k) {
  std::vector<double> v;
  for (const auto& rgb : c) v.push_back(rgb[k]);
  return v;
}

void add_reflectance_panel(Drawing& dr, const analysis::CurveData& d) {
  const Axes a{90, 80, 620, 390, 0, 90, 0, 1};
  add_axes(dr, a, kAngleTicks, nice_ticks(0, 1, 5), "", "reflectance", 0, 1);
  for (size_t m = 0; m < d.models.size(); ++m)
    for (int k = 0; k < 3; ++k)
      dr.add(data_line(a, d.angles_deg, channel(d.models[m].rgb, k), kChannel[k], 1.5,
                       kDash[m % kStyles]));
  for (int k = 0; k < 3; ++k)
    dr.add(data_line(a, d.angles_deg, channel(d.truth, k), kChannel[k], 2.2));
}

void add_de_panel(Drawing& dr, const analysis::CurveData& d) {
  double de_max = 0;
  for (const auto& m : d.models)
    for (double v : m.de2000)
      if (std::isfinite(v)) de_max = std::max(de_max, v);
  const Axes a{90, 530, 620, 220, 0, 90, 0, nice_ceiling(std::max(de_max, 0.5))};
  const auto ticks = nice_ticks(0, a.y_max, 4);
  add_axes(dr, a, kAngleTicks, ticks, "incidence angle θ (degrees)", "ΔE2000", 0,
           tick_decimals(ticks));
  for (size_t m = 0; m < d.models.size(); ++m)
    dr.add(data_line(a, d.angles_deg, d.models[m].de2000, kModel[m % kStyles], 1.8,
                     kDash[m % kStyles]));
}

void add_curve_legend(Drawing& dr, const analysis::CurveData& d) {
  const double lx = 730;
  double y = 96;
  dr.add(Text{lx, y, "reflectance (top)", 13, kInk});
  y += 20;
  for (int k = 0; k < 3; ++k) {
    dr.add(Polyline{{{lx, y - 4}, {lx + 34, y - 4}}, kChannel[k], 2.2, {}});
    dr.add(Text{lx + 42, y, std::string(1, "RGB"[k]) + " ground truth", 12, kInk});
    y += 18;
  }
  dr.add(Text{lx, y, "models: same colours, dashed", 12, kGreyInk});
  y += 34;
  dr.add(Text{lx, y, "models (dash styles)", 13, kInk});
  y += 20;
  for (size_t m = 0; m < d.models.size(); ++m) {
    dr.add(Polyline{{{lx, y - 4}, {lx + 34, y - 4}}, kModel[m % kStyles], 1.8, kDash[m % kStyles]});
    dr.add(Text{lx + 42, y, fmt::format("{} ({:.2f})", d.models[m].name, d.models[m].rms_de2000),
                12, kInk});
    y += 18;
  }
  dr.add(Text{lx, y + 4, "(RMS ΔE2000)", 12, kGreyInk});
}

}  // namespace

Drawing curves_drawing(const analysis::CurveData& d) {
  Drawing dr;
  dr.width = 940;
  dr.height = 820;
  const auto& c = d.caption;
  dr.add(Text{24, 28,
              fmt::format("{}: reflectance and ΔE2000 against angle ({} parameters)", c.material,
                          c.parameter_kind),
              17, kInk});
  dr.add(
      Text{24, 48,
           fmt::format("{} working space, {} illuminant; ΔE2000 against the spectral ground truth",
                       c.space, c.illuminant),
           12, kGreyInk});
  add_reflectance_panel(dr, d);
  add_de_panel(dr, d);
  add_curve_legend(dr, d);
  return dr;
}

}  // namespace fl::draw
