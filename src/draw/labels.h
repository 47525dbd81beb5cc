#pragma once
// Direct labels for the points of a scatter plot: each name set beside its own marker, in the
// marker's colour, placed so that no label covers another label or any marker, with a leader line
// when the nearest free place is away from the point. The palette is qualitative: one distinct hue
// per series, no two alike.
#include <string>
#include <vector>

#include "draw/drawing.h"

namespace fl::draw {

// Ten qualitative colours (Tableau 10 with its grey replaced by a dark teal, which no axis or
// front line uses), each distinct from the others in hue or lightness; series k takes colour
// k mod 10. Past the tenth series the colours repeat, and the series' direct labels tell them apart
// (a new model added to the registry still plots).
io::Rgb8 qualitative_colour(size_t k);
inline constexpr size_t kQualitativeColours = 10;

// `c` darkened for text on white (labels of light hues stay legible).
io::Rgb8 label_ink(io::Rgb8 c);

// An axis-aligned box in pixels: left, top, width, height.
struct Box {
  double x = 0, y = 0, w = 0, h = 0;
  bool overlaps(const Box& o) const {
    return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
  }
};

struct PointLabel {
  Point at;  // the marker's centre
  std::string text;
  io::Rgb8 colour;
};

// Texts (and leader lines) labelling `labels` inside `area`, set at `size_px`. `markers` are the
// boxes of every marker (and every line the labels keep clear of); a label never overlaps one of
// them or an earlier label. Places are tried nearest first: right, left, above, below, then the
// diagonals, then the same directions further out in 8 px steps (a 1 px leader line joins a label
// set away from its marker). A label with no free place inside `area` is set below the area's
// bottom edge, each such label on a row of its own, with a leader.
std::vector<Shape> place_labels(const std::vector<PointLabel>& labels, std::vector<Box> markers,
                                const Box& area, double size_px, const LabelFont& font);

}  // namespace fl::draw
