#pragma once
// A small vector drawing (lines, rectangles, text) for figures, with two back ends: an
// antialiased rasterizer into an Image8 (labels through report/font.h) and hand-written SVG.
// Coordinates are pixels, origin at the top-left, y down.
#include <string>
#include <vector>

#include "report/font.h"
#include "report/image.h"

namespace fl::report {

struct Point {
  double x = 0, y = 0;
};

// Dash pattern in pixels (on, off, on, off, ...); empty: solid.
using Dash = std::vector<double>;

struct Polyline {
  std::vector<Point> points;
  Rgb8 colour;
  double width_px = 1.0;
  Dash dash;
};

struct Rect {
  double x = 0, y = 0, w = 0, h = 0;
  Rgb8 fill;
};

struct Text {
  double x = 0, y = 0;  // baseline anchor (or the centre, when vertical)
  std::string utf8;
  int size_px = 12;
  Rgb8 colour;
  Align align = Align::Left;
  bool vertical = false;  // reading upwards, centred on (x, y)
};

struct Drawing {
  int width = 0, height = 0;
  Rgb8 background{255, 255, 255};
  // Painted in order: rectangles, then lines, then text, each in insertion order.
  std::vector<Rect> rects;
  std::vector<Polyline> lines;
  std::vector<Text> texts;
};

// Distance-based antialiasing (after Gupta & Sproull 1981, "Filtering edges for gray-scale
// displays"): the coverage of a unit pixel by a line of width w whose centre line is d pixels from
// the pixel's centre, approximated by a one-pixel linear ramp across the line's edge,
// clamp(w/2 + 1/2 − d, 0, 1).
double line_coverage(double distance_px, double width_px);

// Splits a polyline into its dashes (each a polyline), by arc length.
std::vector<std::vector<Point>> dash_pieces(const std::vector<Point>& points, const Dash& dash);

Image8 rasterize(const Drawing& d, Font& font);
std::string to_svg(const Drawing& d);

// A plot panel: data ranges mapped onto a pixel rectangle.
struct Axes {
  double left = 0, top = 0, width = 0, height = 0;  // pixels
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;
  Point map(double x, double y) const {
    return {left + (x - x_min) / (x_max - x_min) * width, top + (y_max - y) / (y_max - y_min) * height};
  }
};

// "Nice" tick values (1, 2 or 5 × 10^k steps) covering [lo, hi] with about `target` ticks.
std::vector<double> nice_ticks(double lo, double hi, int target = 5);
// The smallest nice value ≥ v (1, 2, 2.5, 5 × 10^k), for axis maxima.
double nice_ceiling(double v);

// Frame, light grid lines at the ticks, tick labels and axis labels.
void add_axes(Drawing& d, const Axes& a, const std::vector<double>& x_ticks, const std::vector<double>& y_ticks,
              const std::string& x_label, const std::string& y_label, int x_decimals = 0, int y_decimals = 1);
// A data polyline clipped to the panel's y range (points outside are clamped to the frame).
Polyline data_line(const Axes& a, const std::vector<double>& xs, const std::vector<double>& ys, Rgb8 colour,
                   double width_px, Dash dash = {});

}  // namespace fl::report
