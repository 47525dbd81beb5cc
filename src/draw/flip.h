#pragma once
// The frames of `render --compare`'s animated flip: a render with two lines of text under it, and
// per model a difference frame (its ΔE2000 heat map and its amplified signed difference from the
// truth, side by side). Every frame of one flip has the same size: the render's width, and its
// height plus a text band.
#include <string>
#include <vector>

#include "draw/drawing.h"

namespace fl::report {

// The signed difference is shown as mid grey (code 128) + kFlipDifferenceGain × (model − truth)
// per channel of the display codes: a difference of one code shows as 8, and the ramp clips at
// ±16 codes (kFlipDifferenceRange).
constexpr int kFlipDifferenceGain = 8;
constexpr int kFlipDifferenceRange = 16;

// The render (display codes) above a dark band with `label` and, under it in grey, `detail`.
Image8 flip_frame(const Image8& render, const std::string& label, const std::string& detail,
                  const LabelFont& font);

// A model's difference frame, the size of flip_frame(truth, ...): on the left the ΔE2000 heat map
// (heatmap_image on `scale`, each panel half the render's width, 2 × 2 pixels averaged) with an
// inferno bar from 0 to `scale`, on the right signed_difference(truth, model) with its grey ramp
// from −16 to +16 codes; `name` (the model) in the captions, `label` in the band.
Image8 flip_difference_frame(const Image8& truth, const Image8& model,
                             const std::vector<double>& de2000, double scale,
                             const std::string& name, const std::string& label,
                             const LabelFont& font);

// Per channel 128 + kFlipDifferenceGain × (model − truth), clamped to 0–255 (same sizes:
// std::invalid_argument otherwise).
Image8 signed_difference(const Image8& truth, const Image8& model);

// Half the width and height (rounded down), each pixel the mean of a 2 × 2 block, rounded half up.
Image8 half_size(const Image8& image);

}  // namespace fl::report
