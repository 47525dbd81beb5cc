#pragma once
// Every figure is a Drawing: a list of shapes painted in order, in pixel coordinates (origin at the
// top-left, y down). One renderer, Cairo, turns the same Drawing into PNG, SVG or PDF (Cairo stays
// inside draw.cpp and png.cpp). Text is DejaVu Sans, found through fontconfig
// (fonts-dejavu-core), or the TrueType file the command line names (use_label_font).
#include <string>
#include <variant>
#include <vector>

#include "io/image.h"

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

struct Circle {
  double cx = 0, cy = 0, radius_px = 0;
  Rgb8 colour;
  double ring_px = 0;  // 0: a filled disc; otherwise a ring of this width inside the radius
};

enum class Align { Left, Center, Right };

struct Text {
  double x = 0, y = 0;  // baseline anchor (or the centre, when vertical)
  std::string utf8;
  double size_px = 12;  // the em size
  Rgb8 colour;
  Align align = Align::Left;
  bool vertical = false;  // reading upwards, centred on (x, y)
};

// Pixels drawn unscaled with their top-left corner at (x, y) (whole pixels).
struct Picture {
  int x = 0, y = 0;
  Image8 image;
};

using Shape = std::variant<Rect, Polyline, Circle, Text, Picture>;

struct Drawing {
  int width = 0, height = 0;
  Rgb8 background{255, 255, 255};
  std::vector<Shape> shapes;  // painted in insertion order

  template <class S>
  void add(S s) {
    shapes.emplace_back(std::move(s));
  }
};

enum class FileType { Png, Svg, Pdf };

// From the file name's extension (.png, .svg, .pdf, any case); InputError naming the file
// otherwise.
FileType file_type(const std::string& path);

// The file's bytes. PNG: 8-bit RGB, greyscale-antialiased text and lines, no time or text chunks;
// SVG and PDF: vector shapes, text as outlines (SVG) or an embedded font subset (PDF), no creation
// date. The same Drawing gives the same bytes. Throws InputError when the label font cannot be
// loaded.
std::string encode(const Drawing& d, FileType type);

// The drawing's pixels as PNG output paints them (for frames of an animation, or a picture inside
// another drawing).
Image8 rasterize(const Drawing& d);

// The label font's file instead of fontconfig's DejaVu Sans (empty: DejaVu Sans). Takes effect only
// before anything is drawn: the command line calls it once at start.
void use_label_font(const std::string& file);

// The advance width of `utf8` in the label font as PNG output sets it (hinted metrics), for layout.
double text_width_px(const std::string& utf8, double size_px);

// encode() by the extension of `path`, written atomically.
void write_drawing(const std::string& path, const Drawing& d);

}  // namespace fl::report
