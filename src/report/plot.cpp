#include "report/plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace fl::report {

double line_coverage(double distance_px, double width_px) {
  return std::clamp(0.5 * width_px + 0.5 - distance_px, 0.0, 1.0);
}

std::vector<std::vector<Point>> dash_pieces(const std::vector<Point>& points, const Dash& dash) {
  if (dash.empty() || points.size() < 2) return {points};
  std::vector<std::vector<Point>> out;
  size_t k = 0;              // current dash entry (even: drawn, odd: gap)
  double left = dash[0];     // length left in it
  std::vector<Point> cur{points[0]};
  for (size_t i = 1; i < points.size(); ++i) {
    Point a = points[i - 1];
    const Point b = points[i];
    double seg = std::hypot(b.x - a.x, b.y - a.y);
    while (seg > left) {
      const double t = left / seg;
      const Point m{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
      if (k % 2 == 0) {
        cur.push_back(m);
        out.push_back(std::move(cur));
        cur.clear();
      } else {
        cur = {m};
      }
      seg -= left;
      a = m;
      k = (k + 1) % dash.size();
      left = dash[k];
    }
    left -= seg;
    if (k % 2 == 0) cur.push_back(b);
  }
  if (k % 2 == 0 && cur.size() >= 2) out.push_back(std::move(cur));
  return out;
}

namespace {

double distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// Coverage of the whole polyline is the maximum over its segments (so joints and overlapping
// dashes are not painted twice), then composited once.
void draw_polyline(Image8& img, const Polyline& line) {
  const auto pieces = dash_pieces(line.points, line.dash);
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& piece : pieces)
    for (const auto& p : piece) {
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    }
  if (x0 > x1) return;
  const double pad = 0.5 * line.width_px + 1.0;
  const int bx0 = std::max(0, static_cast<int>(std::floor(x0 - pad)));
  const int by0 = std::max(0, static_cast<int>(std::floor(y0 - pad)));
  const int bx1 = std::min(img.width - 1, static_cast<int>(std::ceil(x1 + pad)));
  const int by1 = std::min(img.height - 1, static_cast<int>(std::ceil(y1 + pad)));
  if (bx0 > bx1 || by0 > by1) return;
  const int bw = bx1 - bx0 + 1, bh = by1 - by0 + 1;
  std::vector<float> cov(static_cast<size_t>(bw) * bh, 0.0f);
  for (const auto& piece : pieces) {
    if (piece.empty()) continue;
    const size_t segments = std::max<size_t>(1, piece.size() - 1);  // a lone point is a dot
    for (size_t i = 0; i < segments; ++i) {
      const Point a = piece[i], b = piece[std::min(i + 1, piece.size() - 1)];
      const int sx0 = std::max(bx0, static_cast<int>(std::floor(std::min(a.x, b.x) - pad)));
      const int sx1 = std::min(bx1, static_cast<int>(std::ceil(std::max(a.x, b.x) + pad)));
      const int sy0 = std::max(by0, static_cast<int>(std::floor(std::min(a.y, b.y) - pad)));
      const int sy1 = std::min(by1, static_cast<int>(std::ceil(std::max(a.y, b.y) + pad)));
      for (int y = sy0; y <= sy1; ++y)
        for (int x = sx0; x <= sx1; ++x) {
          const double c = line_coverage(distance_to_segment({x + 0.5, y + 0.5}, a, b), line.width_px);
          float& slot = cov[static_cast<size_t>(y - by0) * bw + (x - bx0)];
          slot = std::max(slot, static_cast<float>(c));
        }
    }
  }
  for (int y = 0; y < bh; ++y)
    for (int x = 0; x < bw; ++x)
      if (const float c = cov[static_cast<size_t>(y) * bw + x]; c > 0) img.blend(bx0 + x, by0 + y, line.colour, c);
}

std::string svg_colour(Rgb8 c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

std::string svg_escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '&') out += "&amp;";
    else if (ch == '<') out += "&lt;";
    else if (ch == '>') out += "&gt;";
    else if (ch == '"') out += "&quot;";
    else out += ch;
  }
  return out;
}

// Fixed two decimals, never "-0.00", so equal drawings give equal files.
std::string num(double v) {
  std::string s = fmt::format("{:.2f}", v);
  if (s == "-0.00") s = "0.00";
  return s;
}

std::string tick_label(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

}  // namespace

Image8 rasterize(const Drawing& d, Font& font) {
  Image8 img(d.width, d.height, d.background);
  for (const auto& r : d.rects)
    img.fill_rect(static_cast<int>(std::lround(r.x)), static_cast<int>(std::lround(r.y)),
                  static_cast<int>(std::lround(r.x + r.w) - std::lround(r.x)),
                  static_cast<int>(std::lround(r.y + r.h) - std::lround(r.y)), r.fill);
  for (const auto& l : d.lines) draw_polyline(img, l);
  for (const auto& t : d.texts) {
    const int x = static_cast<int>(std::lround(t.x)), y = static_cast<int>(std::lround(t.y));
    if (t.vertical) font.draw_vertical(img, x, y, t.utf8, t.size_px, t.colour);
    else font.draw(img, x, y, t.utf8, t.size_px, t.colour, t.align);
  }
  return img;
}

std::string to_svg(const Drawing& d) {
  std::string s = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\">\n"
      "<rect x=\"0\" y=\"0\" width=\"{0}\" height=\"{1}\" fill=\"{2}\"/>\n",
      d.width, d.height, svg_colour(d.background));
  for (const auto& r : d.rects)
    s += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", num(r.x), num(r.y), num(r.w),
                     num(r.h), svg_colour(r.fill));
  for (const auto& l : d.lines) {
    std::string pts;
    for (const auto& p : l.points) pts += (pts.empty() ? "" : " ") + num(p.x) + "," + num(p.y);
    std::string dash;
    if (!l.dash.empty()) {
      dash = " stroke-dasharray=\"";
      for (size_t i = 0; i < l.dash.size(); ++i) dash += (i ? "," : "") + num(l.dash[i]);
      dash += "\"";
    }
    s += fmt::format(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\" "
        "stroke-linecap=\"round\"{}/>\n",
        pts, svg_colour(l.colour), num(l.width_px), dash);
  }
  for (const auto& t : d.texts) {
    const char* anchor = t.vertical || t.align == Align::Center ? "middle" : t.align == Align::Right ? "end" : "start";
    if (t.vertical)
      s += fmt::format(
          "<text x=\"{0}\" y=\"{1}\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"{2}\" fill=\"{3}\" "
          "text-anchor=\"middle\" dominant-baseline=\"central\" transform=\"rotate(-90 {0} {1})\">{4}</text>\n",
          num(t.x), num(t.y), t.size_px, svg_colour(t.colour), svg_escape(t.utf8));
    else
      s += fmt::format(
          "<text x=\"{}\" y=\"{}\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"{}\" fill=\"{}\" "
          "text-anchor=\"{}\">{}</text>\n",
          num(t.x), num(t.y), t.size_px, svg_colour(t.colour), anchor, svg_escape(t.utf8));
  }
  s += "</svg>\n";
  return s;
}

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

void add_axes(Drawing& d, const Axes& a, const std::vector<double>& x_ticks, const std::vector<double>& y_ticks,
              const std::string& x_label, const std::string& y_label, int x_decimals, int y_decimals) {
  const Rgb8 grid{225, 225, 225}, frame{60, 60, 60}, label{30, 30, 30};
  const double right = a.left + a.width, bottom = a.top + a.height;
  for (double x : x_ticks) {
    const double px = a.map(x, a.y_min).x;
    d.lines.push_back({{{px, a.top}, {px, bottom}}, grid, 1.0, {}});
    d.lines.push_back({{{px, bottom}, {px, bottom + 4}}, frame, 1.0, {}});
    d.texts.push_back({px, bottom + 17, tick_label(x, x_decimals), 12, label, Align::Center, false});
  }
  for (double y : y_ticks) {
    const double py = a.map(a.x_min, y).y;
    d.lines.push_back({{{a.left, py}, {right, py}}, grid, 1.0, {}});
    d.lines.push_back({{{a.left - 4, py}, {a.left, py}}, frame, 1.0, {}});
    d.texts.push_back({a.left - 7, py + 4, tick_label(y, y_decimals), 12, label, Align::Right, false});
  }
  d.lines.push_back({{{a.left, a.top}, {right, a.top}, {right, bottom}, {a.left, bottom}, {a.left, a.top}}, frame, 1.0, {}});
  if (!x_label.empty()) d.texts.push_back({a.left + 0.5 * a.width, bottom + 36, x_label, 13, label, Align::Center, false});
  if (!y_label.empty()) d.texts.push_back({a.left - 48, a.top + 0.5 * a.height, y_label, 13, label, Align::Center, true});
}

Polyline data_line(const Axes& a, const std::vector<double>& xs, const std::vector<double>& ys, Rgb8 colour,
                   double width_px, Dash dash) {
  Polyline l{{}, colour, width_px, std::move(dash)};
  for (size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
    if (!std::isfinite(ys[i])) continue;
    l.points.push_back(a.map(xs[i], std::clamp(ys[i], a.y_min, a.y_max)));
  }
  return l;
}

}  // namespace fl::report
