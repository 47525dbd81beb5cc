#include "draw/flip.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "draw/figures.h"

namespace fl::draw {
namespace {

const io::Rgb8 kBackground{24, 24, 24}, kLabel{235, 235, 235}, kDetail{175, 175, 175};

// Text size and band height grow with the frame: 11 px up to 374 px wide, 15 px from 510.
double text_size(int width) {
  return std::clamp(width / 34.0, 11.0, 15.0);
}
int band_height(int width) {
  return static_cast<int>(std::ceil(3.4 * text_size(width)));
}

Drawing frame_drawing(const io::Image8& render) {
  Drawing dr;
  dr.width = render.width;
  dr.height = render.height + band_height(render.width);
  dr.background = kBackground;
  return dr;
}

// `size` (at least kFlipMinTextPx), or smaller down to kFlipMinTextPx so that `text` fits in
// `width` pixels.
double fitted(const std::string& text, double size, double width, const LabelFont& font) {
  return text_size_to_fit(text, std::max(size, kFlipMinTextPx), kFlipMinTextPx, width, font);
}

// The first of `variants` (longest first) that fits `width` at kFlipMinTextPx or more, at the
// size it fits; the last one when none does.
std::pair<std::string, double> legible(const std::vector<std::string>& variants, double size,
                                       double width, const LabelFont& font) {
  for (const auto& v : variants) {
    const double px = fitted(v, size, width, font);
    if (text_width_px(v, px, font) <= width) return {v, px};
  }
  return {variants.back(), kFlipMinTextPx};
}

void add_band(Drawing& dr, int top, const std::vector<std::string>& label,
              const std::vector<std::string>& detail, const LabelFont& font) {
  const double fs = text_size(dr.width), x = dr.width / 2.0, room = dr.width - 8.0;
  const auto [l, l_px] = legible(label, fs, room, font);
  const auto [d, d_px] = legible(detail, fs * 0.9, room, font);
  dr.add(Text{x, top + 1.4 * fs, l, l_px, kLabel, Align::Center});
  dr.add(Text{x, top + 2.8 * fs, d, d_px, kDetail, Align::Center});
}

// A horizontal ramp `width` × `height`: colour(t) for t from 0 at the left to 1 at the right.
template <class Colour>
io::Image8 ramp(int width, int height, Colour colour) {
  io::Image8 bar(width, height);
  for (int x = 0; x < width; ++x)
    for (int y = 0; y < height; ++y) bar.set(x, y, colour(width > 1 ? x / (width - 1.0) : 0.0));
  return bar;
}

io::Rgb8 difference_code(double t) {
  const double d = kFlipDifferenceRange * (2 * t - 1);
  const auto c =
      static_cast<std::uint8_t>(std::clamp(std::lround(128 + kFlipDifferenceGain * d), 0L, 255L));
  return {c, c, c};
}

// The image without `margin` pixels on every side.
io::Image8 cropped(const io::Image8& image, int margin) {
  io::Image8 c(image.width - 2 * margin, image.height - 2 * margin);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) c.set(x, y, image.at(x + margin, y + margin));
  return c;
}

// A panel at (x, y) with its caption above and its ramp, labelled at both ends and the middle,
// below.
struct Panel {
  io::Image8 image, bar;
  std::vector<std::string> caption;  // longest first: the first that fits legibly is set
  std::string low, middle, high;
};
void add_panel(Drawing& dr, const Panel& p, int x, int y, const LabelFont& font) {
  const double fs = text_size(dr.width), w = p.image.width;
  const auto [caption, caption_px] = legible(p.caption, fs, w, font);
  dr.add(Text{x + w / 2, y - 0.6 * fs, caption, caption_px, kLabel, Align::Center});
  dr.add(Picture{x, y, p.image});
  const int bar_y = y + p.image.height + static_cast<int>(0.6 * fs);
  dr.add(Picture{x, bar_y, p.bar});
  const double text_y = bar_y + p.bar.height + 1.2 * fs;
  // The three ramp labels share the panel's width: each fits a third.
  const double small = std::min({fitted(p.low, fs * 0.9, w / 3 - 2, font),
                                 fitted(p.middle, fs * 0.9, w / 3 - 2, font),
                                 fitted(p.high, fs * 0.9, w / 3 - 2, font)});
  dr.add(Text{double(x), text_y, p.low, small, kDetail, Align::Left});
  dr.add(Text{x + w / 2, text_y, p.middle, small, kDetail, Align::Center});
  dr.add(Text{x + w, text_y, p.high, small, kDetail, Align::Right});
}

}  // namespace

Drawing flip_frame_drawing(const io::Image8& render, const std::string& label,
                           const std::string& detail, const LabelFont& font) {
  Drawing dr = frame_drawing(render);
  dr.add(Picture{0, 0, render});
  add_band(dr, render.height, {label}, {detail}, font);
  return dr;
}

io::Image8 flip_frame(const io::Image8& render, const std::string& label, const std::string& detail,
                      const LabelFont& font) {
  return rasterize(flip_frame_drawing(render, label, detail, font), font);
}

io::Image8 signed_difference(const DisplayValues& truth, const DisplayValues& model) {
  if (truth.width != model.width || truth.height != model.height ||
      truth.rgb.size() != model.rgb.size() ||
      truth.rgb.size() != 3 * static_cast<size_t>(truth.width) * truth.height)
    throw std::invalid_argument("signed_difference: images differ in size");
  io::Image8 d(truth.width, truth.height);
  for (size_t k = 0; k < d.pixels.size(); ++k) {
    const double codes = 255.0 * (double(model.rgb[k]) - double(truth.rgb[k]));
    d.pixels[k] = static_cast<std::uint8_t>(
        std::clamp(std::lround(128 + kFlipDifferenceGain * codes), 0L, 255L));
  }
  return d;
}

io::Image8 half_size(const io::Image8& image) {
  io::Image8 h(image.width / 2, image.height / 2);
  const auto code = [&](int x, int y, int c) {
    return int(image.pixels[3 * (static_cast<size_t>(y) * image.width + x) + c]);
  };
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x)
      for (int c = 0; c < 3; ++c)
        h.pixels[3 * (static_cast<size_t>(y) * h.width + x) + c] = static_cast<std::uint8_t>(
            (code(2 * x, 2 * y, c) + code(2 * x + 1, 2 * y, c) + code(2 * x, 2 * y + 1, c) +
             code(2 * x + 1, 2 * y + 1, c) + 2) /
            4);
  return h;
}

Drawing flip_difference_drawing(const DisplayValues& truth, const DisplayValues& model,
                                const std::vector<double>& de2000, double scale,
                                const std::string& name, const std::string& label,
                                const LabelFont& font) {
  Drawing dr = frame_drawing(io::Image8(truth.width, truth.height));
  const int half = truth.width / 2, crop = half / 25, panel = half - 2 * crop;
  const int top = (truth.height - panel) / 2;
  const int bar_h = std::max(4, static_cast<int>(0.6 * text_size(truth.width)));
  const std::string s = fmt::format("{:g}", scale), r = fmt::format("{}", kFlipDifferenceRange);
  const Panel heat{
      cropped(half_size(heatmap_image(de2000, truth.width, truth.height, scale)), crop),
      ramp(panel, bar_h, [](double t) { return inferno(t); }),
      {"ΔE2000 of " + name, "ΔE2000"},
      "0",
      "",
      s};
  const Panel diff{cropped(half_size(signed_difference(truth, model)), crop),
                   ramp(panel, bar_h, difference_code),
                   {fmt::format("{} − truth, ×{}", name, kFlipDifferenceGain),
                    fmt::format("difference ×{}", kFlipDifferenceGain)},
                   "−" + r,
                   "0",
                   "+" + r};
  add_panel(dr, heat, crop, top, font);
  add_panel(dr, diff, truth.width - half + crop, top, font);
  const auto gain = kFlipDifferenceGain;
  add_band(dr, truth.height, {label, name},
           {fmt::format("ΔE2000 on the sheet's scale 0–{}; grey + {} × (model − truth) in codes", s,
                        gain),
            fmt::format("ΔE2000 0–{}; grey + {} × difference in codes", s, gain),
            fmt::format("ΔE2000 0–{}; {} × difference", s, gain)},
           font);
  return dr;
}

io::Image8 flip_difference_frame(const DisplayValues& truth, const DisplayValues& model,
                                 const std::vector<double>& de2000, double scale,
                                 const std::string& name, const std::string& label,
                                 const LabelFont& font) {
  return rasterize(flip_difference_drawing(truth, model, de2000, scale, name, label, font), font);
}

}  // namespace fl::draw
