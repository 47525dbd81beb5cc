#pragma once
// The frames of `render --compare`'s animated flip: a render with two lines of text under it, and
// per model a difference frame (its ΔE2000 heat map and its amplified signed difference from the
// truth, side by side). Every frame of one flip has the same size: the render's width, and its
// height plus a text band.
#include <string>
#include <vector>

#include "draw/drawing.h"

namespace fl::draw {

// The signed difference is shown as mid grey (code 128) + kFlipDifferenceGain × (model − truth)
// per channel, the difference taken between the display-encoded floating-point images (before
// rounding to codes) and expressed in codes (× 255): a model one code brighter shows as a step of
// 32 from mid grey, and the ramp clips at ±4 codes (kFlipDifferenceRange). Taken from 8-bit codes,
// the half-code rounding of either image would show as ±32 contours wherever the two differ by
// less than a code. Through the ACES view, models a few ΔE2000 off differ from the truth by a few
// codes (gold under the sunset: Schlick and F82, up to 2.4 ΔE2000, by at most 3), which a gain of 8
// would leave within 24 levels of mid grey, hard to see.
constexpr int kFlipDifferenceGain = 32;
constexpr int kFlipDifferenceRange = 128 / kFlipDifferenceGain;

// Display-encoded floats in [0, 1], 3 per pixel, row by row.
struct DisplayValues {
  int width = 0, height = 0;
  std::vector<float> rgb;
};

// Every text of a flip frame is at least this size (its x-height about 5.5 px in DejaVu Sans),
// in frames of any width: a caption too long for its room at this size gives way to a shorter
// wording (the model's name alone, "ΔE2000", "difference ×32") rather than shrinking further.
inline constexpr double kFlipMinTextPx = 10;

// The render (display codes) above a dark band with `label` and, under it in grey, `detail`.
Drawing flip_frame_drawing(const io::Image8& render, const std::string& label,
                           const std::string& detail, const LabelFont& font);
// flip_frame_drawing's pixels.
io::Image8 flip_frame(const io::Image8& render, const std::string& label, const std::string& detail,
                      const LabelFont& font);

// A model's difference frame, the size of flip_frame(truth, ...): on the left the ΔE2000 heat map
// (heatmap_image on `scale`), on the right signed_difference(truth, model), each panel at half the
// render's size (2 × 2 pixels averaged, a 25th of the empty margin cropped from each side), with a
// ramp under it (inferno from 0 to `scale`; grey from −4 to +4 codes); `name` (the model) in the
// captions where it fits, `label` (else `name`) in the band.
Drawing flip_difference_drawing(const DisplayValues& truth, const DisplayValues& model,
                                const std::vector<double>& de2000, double scale,
                                const std::string& name, const std::string& label,
                                const LabelFont& font);
// flip_difference_drawing's pixels.
io::Image8 flip_difference_frame(const DisplayValues& truth, const DisplayValues& model,
                                 const std::vector<double>& de2000, double scale,
                                 const std::string& name, const std::string& label,
                                 const LabelFont& font);

// Per channel 128 + kFlipDifferenceGain × 255 × (model − truth), rounded and clamped to 0–255
// (same sizes: std::invalid_argument otherwise).
io::Image8 signed_difference(const DisplayValues& truth, const DisplayValues& model);

// Half the width and height (rounded down), each pixel the mean of a 2 × 2 block, rounded half up.
io::Image8 half_size(const io::Image8& image);

}  // namespace fl::draw
