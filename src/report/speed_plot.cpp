#include "report/speed_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "report/png.h"
#include "spectral/errors.h"

namespace fl::report {

namespace {

// A 5×7 bitmap font (lowercase, digits, a little punctuation), one string of 7 rows per glyph.
struct Glyph {
  char ch;
  const char* rows[7];
};
constexpr Glyph kFont[] = {
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'_', {".....", ".....", ".....", ".....", ".....", ".....", "#####"}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {'/', {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."}},
    {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
    {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
    {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
    {'a', {".....", ".....", ".###.", "....#", ".####", "#...#", ".####"}},
    {'b', {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "####."}},
    {'c', {".....", ".....", ".###.", "#....", "#....", "#...#", ".###."}},
    {'d', {"....#", "....#", ".##.#", "#..##", "#...#", "#...#", ".####"}},
    {'e', {".....", ".....", ".###.", "#...#", "#####", "#....", ".###."}},
    {'f', {"..##.", ".#..#", ".#...", "###..", ".#...", ".#...", ".#..."}},
    {'g', {".....", ".####", "#...#", "#...#", ".####", "....#", ".###."}},
    {'h', {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "#...#"}},
    {'i', {"..#..", ".....", ".##..", "..#..", "..#..", "..#..", ".###."}},
    {'j', {"...#.", ".....", "..##.", "...#.", "...#.", "#..#.", ".##.."}},
    {'k', {"#....", "#....", "#..#.", "#.#..", "##...", "#.#..", "#..#."}},
    {'l', {".##..", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'m', {".....", ".....", "##.#.", "#.#.#", "#.#.#", "#...#", "#...#"}},
    {'n', {".....", ".....", "#.##.", "##..#", "#...#", "#...#", "#...#"}},
    {'o', {".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###."}},
    {'p', {".....", ".....", "####.", "#...#", "####.", "#....", "#...."}},
    {'q', {".....", ".....", ".##.#", "#..##", ".####", "....#", "....#"}},
    {'r', {".....", ".....", "#.##.", "##..#", "#....", "#....", "#...."}},
    {'s', {".....", ".....", ".###.", "#....", ".###.", "....#", "####."}},
    {'t', {".#...", ".#...", "###..", ".#...", ".#...", ".#..#", "..##."}},
    {'u', {".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#"}},
    {'v', {".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'w', {".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#."}},
    {'x', {".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"}},
    {'y', {".....", ".....", "#...#", "#...#", ".####", "....#", ".###."}},
    {'z', {".....", ".....", "#####", "...#.", "..#..", ".#...", "#####"}},
};
constexpr int kGlyphW = 5, kGlyphH = 7;

const Glyph* find_glyph(char ch) {
  ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (const auto& g : kFont)
    if (g.ch == ch) return &g;
  return nullptr;
}

// Text with its top-left corner at (x, y); each font pixel is a scale×scale block.
void draw_text(Image8& img, int x, int y, const std::string& s, Rgb8 c, int scale = 2) {
  for (const char ch : s) {
    if (const Glyph* g = find_glyph(ch))
      for (int r = 0; r < kGlyphH; ++r)
        for (int k = 0; k < kGlyphW; ++k)
          if (g->rows[r][k] == '#') img.fill_rect(x + k * scale, y + r * scale, scale, scale, c);
    x += (kGlyphW + 1) * scale;
  }
}
int text_width(const std::string& s, int scale = 2) { return static_cast<int>(s.size()) * (kGlyphW + 1) * scale; }

// Text rotated 90° counter-clockwise (reads bottom to top), its baseline-left corner at (x, y).
void draw_text_vertical(Image8& img, int x, int y, const std::string& s, Rgb8 c, int scale = 2) {
  for (const char ch : s) {
    if (const Glyph* g = find_glyph(ch))
      for (int r = 0; r < kGlyphH; ++r)
        for (int k = 0; k < kGlyphW; ++k)
          if (g->rows[r][k] == '#') img.fill_rect(x + r * scale, y - (k + 1) * scale, scale, scale, c);
    y -= (kGlyphW + 1) * scale;
  }
}

// Bresenham line, `w` pixels wide.
void draw_line(Image8& img, int x0, int y0, int x1, int y1, Rgb8 c, int w = 1) {
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  for (;;) {
    img.fill_rect(x0 - w / 2, y0 - w / 2, w, w, c);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
}

void draw_marker(Image8& img, int x, int y, Rgb8 c, bool filled) {
  constexpr int kRadius = 6;
  for (int dy = -kRadius; dy <= kRadius; ++dy)
    for (int dx = -kRadius; dx <= kRadius; ++dx) {
      const int d2 = dx * dx + dy * dy;
      const bool inside = d2 <= kRadius * kRadius;
      const bool ring = inside && d2 >= (kRadius - 2) * (kRadius - 2);
      if (filled ? inside : ring) img.set(x + dx, y + dy, c);
    }
}

// Log-scale axis range covering [lo, hi] with whole decades or 1-2-5 steps at its ends.
struct LogAxis {
  double lo, hi;  // log10 of the range ends
  int to_pixel(double v, int p0, int p1) const {
    const double t = (std::log10(v) - lo) / (hi - lo);
    return static_cast<int>(std::lround(p0 + t * (p1 - p0)));
  }
};
LogAxis log_axis(double lo, double hi) {
  auto down = [](double v) {
    const double d = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {5.0, 2.0, 1.0})
      if (m * d <= v) return m * d;
    return d;
  };
  auto up = [](double v) {
    const double d = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (m * d >= v) return m * d;
    return 10.0 * d;
  };
  return {std::log10(down(lo)), std::log10(up(hi))};
}
// 1-2-5 ticks inside the axis.
std::vector<double> ticks(const LogAxis& a) {
  std::vector<double> out;
  for (int e = static_cast<int>(std::floor(a.lo)) - 1; e <= static_cast<int>(std::ceil(a.hi)); ++e)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (std::log10(v) >= a.lo - 1e-9 && std::log10(v) <= a.hi + 1e-9) out.push_back(v);
    }
  return out;
}
std::string tick_label(double v) { return v >= 1 ? fmt::format("{:g}", v) : fmt::format("{:.{}f}", v, -static_cast<int>(std::floor(std::log10(v) + 1e-9))); }

// One colour per model (model_specs() order), distinguishable on white.
constexpr Rgb8 kModelColours[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                  {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}};

}  // namespace

void check_png_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext != ".png") throw InputError(path, 0, "the plot is written as PNG: expected a .png file name");
}

Image8 speed_plot(const std::vector<analysis::SpeedRow>& rows) {
  constexpr int kWidth = 960, kHeight = 560;
  constexpr int kLeft = 90, kRight = 660, kTop = 50, kBottom = 480;
  const Rgb8 black{0, 0, 0}, grid{225, 225, 225}, grey{90, 90, 90};
  Image8 img(kWidth, kHeight);
  double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0;
  for (const auto& r : rows) {
    xmin = std::min(xmin, r.ns_per_eval), xmax = std::max(xmax, r.ns_per_eval);
    const double e = std::max(r.median_rms_de00, 1e-3);
    ymin = std::min(ymin, e), ymax = std::max(ymax, e);
  }
  if (rows.empty()) xmin = ymin = 0.1, xmax = ymax = 10;
  const LogAxis ax = log_axis(xmin, xmax), ay = log_axis(ymin, ymax);
  auto px = [&](double v) { return ax.to_pixel(v, kLeft, kRight); };
  auto py = [&](double v) { return ay.to_pixel(std::max(v, 1e-3), kBottom, kTop); };
  for (double t : ticks(ax)) {
    draw_line(img, px(t), kTop, px(t), kBottom, grid);
    const auto s = tick_label(t);
    draw_text(img, px(t) - text_width(s) / 2, kBottom + 8, s, grey);
  }
  for (double t : ticks(ay)) {
    draw_line(img, kLeft, py(t), kRight, py(t), grid);
    const auto s = tick_label(t);
    draw_text(img, kLeft - 8 - text_width(s), py(t) - kGlyphH, s, grey);
  }
  draw_line(img, kLeft, kBottom, kRight, kBottom, black);
  draw_line(img, kLeft, kTop, kLeft, kBottom, black);
  const std::string title = "median rms de2000 against cost (batched float)";
  draw_text(img, (kLeft + kRight - text_width(title)) / 2, 16, title, black);
  const std::string xl = "ns per evaluation (log)";
  draw_text(img, (kLeft + kRight - text_width(xl)) / 2, kBottom + 36, xl, black);
  const std::string yl = "median rms de2000 (log)";
  draw_text_vertical(img, 14, (kTop + kBottom + text_width(yl)) / 2, yl, black);

  // The Pareto front, cheapest first, as a staircase.
  std::vector<analysis::SpeedRow> front;
  for (const auto& r : rows)
    if (r.pareto) front.push_back(r);
  std::sort(front.begin(), front.end(), [](const auto& a, const auto& b) {
    return a.ns_per_eval != b.ns_per_eval ? a.ns_per_eval < b.ns_per_eval : a.median_rms_de00 > b.median_rms_de00;
  });
  for (size_t i = 1; i < front.size(); ++i) {
    const int x0 = px(front[i - 1].ns_per_eval), y0 = py(front[i - 1].median_rms_de00);
    const int x1 = px(front[i].ns_per_eval), y1 = py(front[i].median_rms_de00);
    draw_line(img, x0, y0, x1, y0, grey, 2);
    draw_line(img, x1, y0, x1, y1, grey, 2);
  }
  const auto& specs = fresnel::model_specs();
  for (const auto& r : rows) {
    const size_t k = static_cast<size_t>(std::find_if(specs.begin(), specs.end(), [&](const auto& s) { return s.model == r.model; }) - specs.begin());
    draw_marker(img, px(r.ns_per_eval), py(r.median_rms_de00), kModelColours[k % std::size(kModelColours)], r.fitted);
  }
  // Legend.
  int ly = kTop;
  const int lx = kRight + 30;
  for (size_t k = 0; k < specs.size(); ++k) {
    draw_marker(img, lx + 6, ly + 7, kModelColours[k % std::size(kModelColours)], true);
    draw_text(img, lx + 20, ly, specs[k].name, black);
    ly += 26;
  }
  ly += 10;
  draw_marker(img, lx + 6, ly + 7, grey, true);
  draw_text(img, lx + 20, ly, "fitted", black);
  ly += 26;
  draw_marker(img, lx + 6, ly + 7, grey, false);
  draw_text(img, lx + 20, ly, "derived", black);
  ly += 26;
  draw_line(img, lx, ly + 7, lx + 14, ly + 7, grey, 2);
  draw_text(img, lx + 20, ly, "pareto front", black);
  return img;
}

void write_speed_plot(const std::string& path, const std::vector<analysis::SpeedRow>& rows) {
  check_png_path(path);
  write_png_atomic(path, speed_plot(rows));
}

}  // namespace fl::report
