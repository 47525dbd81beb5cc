#pragma once
// Plot panels on a Drawing (drawing.h): data ranges mapped onto a pixel rectangle, ticks, axes.
#include <string>
#include <vector>

#include "draw/drawing.h"

namespace fl::draw {

const io::Rgb8 kInk{30, 30, 30};
const io::Rgb8 kGreyInk{110, 110, 110};

struct Axes {
  double left = 0, top = 0, width = 0, height = 0;  // pixels
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;
  Point map(double x, double y) const {
    return {left + (x - x_min) / (x_max - x_min) * width,
            top + (y_max - y) / (y_max - y_min) * height};
  }
};

// "Nice" tick values (1, 2 or 5 × 10^k steps) covering [lo, hi] with about `target` ticks.
std::vector<double> nice_ticks(double lo, double hi, int target = 5);
// The smallest nice value ≥ v (1, 2, 2.5, 5 × 10^k), for axis maxima.
double nice_ceiling(double v);
// The fewest decimals (at most 4) that print every tick exactly.
int tick_decimals(const std::vector<double>& ticks);
// `v` with `decimals` decimals, never "-0".
std::string tick_label(double v, int decimals);

// The centre of the pixel column or row containing v: a 1 px line there covers one whole pixel.
double pixel_centre(double v);

// A 1 px straight line between two points, both snapped to pixel centres.
Polyline hairline(Point a, Point b, io::Rgb8 colour);

// Frame, light grid lines at the ticks, tick labels and axis labels.
void add_axes(Drawing& d, const Axes& a, const std::vector<double>& x_ticks,
              const std::vector<double>& y_ticks, const std::string& x_label,
              const std::string& y_label, int x_decimals = 0, int y_decimals = 1);
// A data polyline clipped to the panel's y range (points outside are clamped to the frame).
Polyline data_line(const Axes& a, const std::vector<double>& xs, const std::vector<double>& ys,
                   io::Rgb8 colour, double width_px, Dash dash = {});

}  // namespace fl::draw
