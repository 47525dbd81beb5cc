#include "draw/speed_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "draw/labels.h"
#include "draw/plot.h"
#include "io/writer.h"

namespace fl::draw {
namespace {

constexpr int kWidth = 960, kHeight = 560;
constexpr double kLeft = 90, kRight = 760, kTop = 50, kBottom = 480;
constexpr double kMarkerRadius = 6, kFloorDe = 1e-3;  // errors below the floor are drawn at it
const io::Rgb8 kFrame{60, 60, 60}, kGrid{225, 225, 225}, kFront{90, 90, 90};

// A log-scale axis range covering [lo, hi], its ends on 1-2-5 values.
struct LogAxis {
  double lo, hi;  // log10 of the range ends
  double to_pixel(double v, double p0, double p1) const {
    return p0 + (std::log10(v) - lo) / (hi - lo) * (p1 - p0);
  }
};

LogAxis log_axis(double lo, double hi) {
  const auto down = [](double v) {
    const double d = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {5.0, 2.0, 1.0})
      if (m * d <= v) return m * d;
    return d;
  };
  const auto up = [](double v) {
    const double d = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (m * d >= v) return m * d;
    return 10.0 * d;
  };
  return {std::log10(down(lo)), std::log10(up(hi))};
}

// 1-2-5 ticks inside the axis.
std::vector<double> log_ticks(const LogAxis& a) {
  std::vector<double> out;
  for (int e = static_cast<int>(std::floor(a.lo)) - 1; e <= static_cast<int>(std::ceil(a.hi)); ++e)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (std::log10(v) >= a.lo - 1e-9 && std::log10(v) <= a.hi + 1e-9) out.push_back(v);
    }
  return out;
}

std::string log_tick_label(double v) {
  return v >= 1 ? fmt::format("{:g}", v)
                : tick_label(v, -static_cast<int>(std::floor(std::log10(v) + 1e-9)));
}

struct SpeedAxes {
  LogAxis x, y;
  Point map(double ns, double de) const {
    return {x.to_pixel(ns, kLeft, kRight), y.to_pixel(std::max(de, kFloorDe), kBottom, kTop)};
  }
};

SpeedAxes speed_axes(const std::vector<analysis::SpeedRow>& rows) {
  if (rows.empty()) return {log_axis(0.1, 10), log_axis(0.1, 10)};
  double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0;
  for (const auto& r : rows) {
    xmin = std::min(xmin, *r.ns_per_eval), xmax = std::max(xmax, *r.ns_per_eval);
    const double e = std::max(r.median_rms_de00, kFloorDe);
    ymin = std::min(ymin, e), ymax = std::max(ymax, e);
  }
  return {log_axis(xmin, xmax), log_axis(ymin, ymax)};
}

void add_speed_axes(Drawing& d, const SpeedAxes& a) {
  for (double t : log_ticks(a.x)) {
    const double px = std::min(a.map(t, 1).x, kRight - 0.5);
    d.add(hairline({px, kTop}, {px, kBottom}, kGrid));
    d.add(Text{pixel_centre(px), kBottom + 18, log_tick_label(t), 12, kInk, Align::Center});
  }
  for (double t : log_ticks(a.y)) {
    const double py = std::min(a.map(1, t).y, kBottom - 0.5);
    d.add(hairline({kLeft, py}, {kRight, py}, kGrid));
    d.add(Text{kLeft - 8, pixel_centre(py) + 4, log_tick_label(t), 12, kInk, Align::Right});
  }
  d.add(Polyline{{{kLeft + 0.5, kTop}, {kLeft + 0.5, kBottom - 0.5}, {kRight, kBottom - 0.5}},
                 kFrame,
                 1.0,
                 {}});
  d.add(Text{0.5 * (kLeft + kRight), 28, "Median RMS ΔE2000 against cost (batched float)", 15, kInk,
             Align::Center});
  d.add(Text{0.5 * (kLeft + kRight), kBottom + 40, "ns per evaluation (log scale)", 13, kInk,
             Align::Center});
  d.add(Text{28, 0.5 * (kTop + kBottom), "median RMS ΔE2000 over the catalog (log scale)", 13, kInk,
             Align::Center, true});
}

// The Pareto front, cheapest first, as the points of a staircase.
std::vector<Point> front_points(const SpeedAxes& a, const std::vector<analysis::SpeedRow>& rows) {
  std::vector<analysis::SpeedRow> front;
  for (const auto& r : rows)
    if (r.pareto) front.push_back(r);
  std::sort(front.begin(), front.end(), [](const auto& p, const auto& q) {
    return p.ns_per_eval != q.ns_per_eval ? p.ns_per_eval < q.ns_per_eval
                                          : p.median_rms_de00 > q.median_rms_de00;
  });
  std::vector<Point> points;
  for (size_t i = 0; i < front.size(); ++i) {
    const Point p = a.map(*front[i].ns_per_eval, front[i].median_rms_de00);
    if (i > 0) points.push_back({p.x, points.back().y});
    points.push_back(p);
  }
  return points;
}

void add_pareto_front(Drawing& d, const std::vector<Point>& front) {
  if (front.size() > 1) d.add(Polyline{front, kFront, 2.0, {}});
}

// One qualitative colour per model, in model_specs() order.
io::Rgb8 model_colour(fresnel::Model m) {
  return qualitative_colour(static_cast<size_t>(m.index()));
}

Circle marker(Point p, io::Rgb8 colour, bool filled) {
  return {p.x, p.y, kMarkerRadius, colour, filled ? 0.0 : 2.0};
}

// What the marker styles mean; the models are named beside their markers.
void add_speed_legend(Drawing& d) {
  const double lx = kRight + 30;
  double y = kTop + 7;
  const auto entry = [&](Shape symbol, const std::string& label) {
    d.add(std::move(symbol));
    d.add(Text{lx + 18, y + 5, label, 13, kInk});
    y += 24;
  };
  entry(marker({lx + 6, y}, kFront, true), "fitted");
  entry(marker({lx + 6, y}, kFront, false), "derived");
  entry(Polyline{{{lx - 1, y}, {lx + 13, y}}, kFront, 2.0, {}}, "Pareto front");
}

// Each model's name beside its fitted marker (its derived one when it has no fit), clear of every
// marker and of the front's steps.
void add_model_labels(Drawing& d, const SpeedAxes& a, const std::vector<analysis::SpeedRow>& rows,
                      const std::vector<Point>& front, const LabelFont& font) {
  std::vector<Box> markers;
  for (size_t i = 1; i < front.size(); ++i) {
    const Point p = front[i - 1], q = front[i];
    markers.push_back({std::min(p.x, q.x) - 1.5, std::min(p.y, q.y) - 1.5, std::abs(q.x - p.x) + 3,
                       std::abs(q.y - p.y) + 3});
  }
  for (const auto& r : rows) {
    const Point p = a.map(*r.ns_per_eval, r.median_rms_de00);
    markers.push_back(
        {p.x - kMarkerRadius, p.y - kMarkerRadius, 2 * kMarkerRadius, 2 * kMarkerRadius});
  }
  std::vector<PointLabel> labels;
  for (const auto& s : fresnel::model_specs()) {
    const analysis::SpeedRow* at = nullptr;
    for (const auto& r : rows)
      if (r.model == s.model && (!at || (r.fitted && !at->fitted))) at = &r;
    if (at)
      labels.push_back(
          {a.map(*at->ns_per_eval, at->median_rms_de00), s.name, model_colour(s.model)});
  }
  for (auto& shape :
       place_labels(labels, markers, {kLeft + 2, kTop + 2, kRight - kLeft - 4, kBottom - kTop - 4},
                    12, font))
    d.shapes.push_back(std::move(shape));
}

}  // namespace

Drawing speed_plot(const std::vector<analysis::SpeedRow>& all_rows, const LabelFont& font) {
  // Only the rows with a measured CPU cost have a place on the cost axis.
  std::vector<analysis::SpeedRow> rows;
  std::copy_if(all_rows.begin(), all_rows.end(), std::back_inserter(rows),
               [](const analysis::SpeedRow& r) { return r.ns_per_eval.has_value(); });
  Drawing d;
  d.width = kWidth;
  d.height = kHeight;
  const SpeedAxes a = speed_axes(rows);
  add_speed_axes(d, a);
  const auto front = front_points(a, rows);
  add_pareto_front(d, front);
  for (const auto& r : rows)
    d.add(marker(a.map(*r.ns_per_eval, r.median_rms_de00), model_colour(r.model), r.fitted));
  add_model_labels(d, a, rows, front, font);
  add_speed_legend(d);
  return d;
}

void write_speed_plot(const std::string& path, const std::vector<analysis::SpeedRow>& rows,
                      const LabelFont& font) {
  const FileType type = file_type(path);
  io::write_file_atomic(path, encode(speed_plot(rows, font), type, font));
}

}  // namespace fl::draw
