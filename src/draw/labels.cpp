#include "draw/labels.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace fl::draw {
namespace {

// DejaVu Sans's ascent and descent (hhea), in em: the height a label's box reserves.
constexpr double kAscentEm = 0.93, kDescentEm = 0.24;
constexpr double kGapPx = 3;   // between a marker and its label
constexpr double kStepPx = 8;  // further-out rings
constexpr int kRings = 30;

const io::Rgb8 kPalette[kQualitativeColours] = {
    {31, 119, 180}, {255, 127, 14},  {44, 160, 44}, {214, 39, 40},  {148, 103, 189},
    {140, 86, 75},  {227, 119, 194}, {0, 95, 95},   {188, 189, 34}, {23, 190, 207}};

bool inside(const Box& b, const Box& area) {
  return b.x >= area.x && b.y >= area.y && b.x + b.w <= area.x + area.w &&
         b.y + b.h <= area.y + area.h;
}

bool free_place(const Box& b, const std::vector<Box>& taken) {
  for (const auto& t : taken)
    if (b.overlaps(t)) return false;
  return true;
}

// The label box of size (w, h) `distance` px from `p` in direction k of 8 (right, left, above,
// below, then the diagonals).
Box candidate(Point p, double w, double h, double distance, int k) {
  static const double dx[] = {1, -1, 0, 0, 1, -1, 1, -1}, dy[] = {0, 0, -1, 1, -1, -1, 1, 1};
  const double cx = p.x + dx[k] * (distance + w / 2), cy = p.y + dy[k] * (distance + h / 2);
  return {cx - w / 2, cy - h / 2, w, h};
}

// The point of `b` nearest to `p`, where a leader line ends.
Point nearest_on(const Box& b, Point p) {
  return {std::clamp(p.x, b.x, b.x + b.w), std::clamp(p.y, b.y, b.y + b.h)};
}

}  // namespace

io::Rgb8 qualitative_colour(size_t k) {
  return kPalette[k % kQualitativeColours];
}

io::Rgb8 label_ink(io::Rgb8 c) {
  const auto dark = [](unsigned char v) { return static_cast<unsigned char>(v * 0.7); };
  return {dark(c.r), dark(c.g), dark(c.b)};
}

std::vector<Shape> place_labels(const std::vector<PointLabel>& labels, std::vector<Box> markers,
                                const Box& area, double size_px, const LabelFont& font) {
  std::vector<Shape> out;
  double overflow_y = area.y + area.h + kGapPx;
  for (const auto& l : labels) {
    const double w = text_width_px(l.text, size_px, font) + 2,
                 h = (kAscentEm + kDescentEm) * size_px + 2;
    std::optional<Box> place;
    int ring = 0;
    for (; ring < kRings && !place; ++ring)
      for (int k = 0; k < 8 && !place; ++k) {
        const Box b = candidate(l.at, w, h, kGapPx + 6 + ring * kStepPx, k);
        if (inside(b, area) && free_place(b, markers)) place = b;
      }
    if (!place) {
      place = Box{l.at.x - w / 2, overflow_y, w, h};
      overflow_y += h;
      ring = kRings;
    }
    if (ring > 1) {
      const Point end = nearest_on(*place, l.at);
      out.emplace_back(Polyline{{l.at, end}, l.colour, 1.0, {}});
    }
    out.emplace_back(Text{place->x + 1, place->y + 1 + kAscentEm * size_px, l.text, size_px,
                          label_ink(l.colour), Align::Left});
    markers.push_back(*place);  // later labels keep clear of this one
  }
  return out;
}

}  // namespace fl::draw
