#include "draw/plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace fl::draw {

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / std::max(1, target);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> out;
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
    out.push_back(std::fabs(v) < 1e-12 * step ? 0.0 : v);
  return out;
}

double nice_ceiling(double v) {
  if (!(v > 0)) return 1.0;
  const double mag = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= v * (1 - 1e-12)) return m * mag;
  return 10.0 * mag;
}

int tick_decimals(const std::vector<double>& ticks) {
  for (int decimals = 0; decimals < 4; ++decimals) {
    const double scale = std::pow(10.0, decimals);
    if (std::all_of(ticks.begin(), ticks.end(),
                    [&](double v) { return std::fabs(v * scale - std::round(v * scale)) < 1e-6; }))
      return decimals;
  }
  return 4;
}

std::string tick_label(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

double pixel_centre(double v) {
  return std::floor(v) + 0.5;
}

Polyline hairline(Point a, Point b, io::Rgb8 colour) {
  return {{{pixel_centre(a.x), pixel_centre(a.y)}, {pixel_centre(b.x), pixel_centre(b.y)}},
          colour,
          1.0,
          {}};
}

void add_axes(Drawing& d, const Axes& a, const std::vector<double>& x_ticks,
              const std::vector<double>& y_ticks, const std::string& x_label,
              const std::string& y_label, int x_decimals, int y_decimals) {
  const io::Rgb8 grid{225, 225, 225}, frame{60, 60, 60};
  const double right = a.left + a.width, bottom = a.top + a.height;
  for (double x : x_ticks) {
    const double px = std::min(a.map(x, a.y_min).x, right - 0.5);
    d.add(hairline({px, a.top}, {px, bottom}, grid));
    d.add(hairline({px, bottom}, {px, bottom + 4}, frame));
    d.add(Text{px, bottom + 17, tick_label(x, x_decimals), 12, kInk, Align::Center, false});
  }
  for (double y : y_ticks) {
    const double py = std::min(a.map(a.x_min, y).y, bottom - 0.5);
    d.add(hairline({a.left, py}, {right, py}, grid));
    d.add(hairline({a.left - 4, py}, {a.left, py}, frame));
    d.add(Text{a.left - 7, py + 4, tick_label(y, y_decimals), 12, kInk, Align::Right, false});
  }
  const double l = pixel_centre(a.left), t = pixel_centre(a.top);
  const double r = pixel_centre(right - 0.5), b = pixel_centre(bottom - 0.5);
  d.add(Polyline{{{l, t}, {r, t}, {r, b}, {l, b}, {l, t}}, frame, 1.0, {}});
  if (!x_label.empty())
    d.add(Text{a.left + 0.5 * a.width, bottom + 36, x_label, 13, kInk, Align::Center, false});
  if (!y_label.empty())
    d.add(Text{a.left - 48, a.top + 0.5 * a.height, y_label, 13, kInk, Align::Center, true});
}

Polyline data_line(const Axes& a, const std::vector<double>& xs, const std::vector<double>& ys,
                   io::Rgb8 colour, double width_px, Dash dash) {
  Polyline l{{}, colour, width_px, std::move(dash)};
  for (size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
    if (!std::isfinite(ys[i])) continue;
    l.points.push_back(a.map(xs[i], std::clamp(ys[i], a.y_min, a.y_max)));
  }
  return l;
}

}  // namespace fl::draw
