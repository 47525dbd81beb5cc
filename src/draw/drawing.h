#pragma once
// Every figure is a Drawing: a list of shapes painted in order, in pixel coordinates (origin at the
// top-left, y down). One renderer, Cairo, turns the same Drawing into pixels (encoded as PNG by
// png.h), SVG or PDF (Cairo stays inside drawing.cpp and png.cpp). Text is set in a LabelFont the
// caller owns: DejaVu Sans, found through fontconfig (fonts-dejavu-core), or the TrueType file the
// command line names.
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "io/image.h"

namespace fl::draw {

struct Point {
  double x = 0, y = 0;
};

// Dash pattern in pixels (on, off, on, off, ...); empty: solid.
using Dash = std::vector<double>;

struct Polyline {
  std::vector<Point> points;
  io::Rgb8 colour;
  double width_px = 1.0;
  Dash dash;
};

struct Rect {
  double x = 0, y = 0, w = 0, h = 0;
  io::Rgb8 fill;
};

struct Circle {
  double cx = 0, cy = 0, radius_px = 0;
  io::Rgb8 colour;
  double ring_px = 0;  // 0: a filled disc; otherwise a ring of this width inside the radius
};

enum class Align { Left, Center, Right };

struct Text {
  double x = 0, y = 0;  // baseline anchor (or the centre, when vertical)
  std::string utf8;
  double size_px = 12;  // the em size
  io::Rgb8 colour;
  Align align = Align::Left;
  bool vertical = false;  // reading upwards, centred on (x, y)
};

// Pixels drawn unscaled with their top-left corner at (x, y) (whole pixels).
struct Picture {
  int x = 0, y = 0;
  io::Image8 image;
};

using Shape = std::variant<Rect, Polyline, Circle, Text, Picture>;

struct Drawing {
  int width = 0, height = 0;
  io::Rgb8 background{255, 255, 255};
  std::vector<Shape> shapes;  // painted in insertion order

  template <class S>
  void add(S s) {
    shapes.emplace_back(std::move(s));
  }
};

// The font labels are set in, loaded when constructed: the TrueType or OpenType `file`, or (empty)
// the file fontconfig gives for DejaVu Sans. InputError when that cannot be loaded: the file named
// ("cannot load the label font"), or DejaVu Sans not found (fontconfig gives another family, which
// would change every figure). Copies share the one loaded face, which threads may use at once. The
// command that draws creates it and passes it to everything that sets or measures text.
class LabelFont {
 public:
  explicit LabelFont(const std::string& file = "");
  // The font file in use.
  const std::string& file() const { return file_; }

  struct Face;  // Cairo's face for the file (drawing.cpp)
  const Face& face() const { return *face_; }

 private:
  std::string file_;
  std::shared_ptr<const Face> face_;
};

enum class FileType { Png, Svg, Pdf };

// From the file name's extension (.png, .svg, .pdf, any case); InputError naming the file
// otherwise.
FileType file_type(const std::string& path);

// The file's bytes. PNG: 8-bit RGB, greyscale-antialiased text and lines, no time or text chunks;
// SVG and PDF: vector shapes, text as outlines (SVG) or an embedded font subset (PDF), no creation
// date. Text is set in `font`. The same Drawing and font give the same bytes.
std::string encode(const Drawing& d, FileType type, const LabelFont& font);

// The drawing's pixels as PNG output paints them (for frames of an animation, or a picture inside
// another drawing).
io::Image8 rasterize(const Drawing& d, const LabelFont& font);

// The advance width of `utf8` in `font` as PNG output sets it (hinted metrics), for layout.
double text_width_px(const std::string& utf8, double size_px, const LabelFont& font);
// size_px, or the largest size below it in half-pixel steps (hinted widths do not scale exactly
// with the size) at which `utf8` is at most width_px wide, but not below min_px.
double text_size_to_fit(const std::string& utf8, double size_px, double min_px, double width_px,
                        const LabelFont& font);

// encode() by the extension of `path`, written atomically.
void write_drawing(const std::string& path, const Drawing& d, const LabelFont& font);

}  // namespace fl::draw
