#include "report/image.h"

#include <algorithm>
#include <cmath>

namespace fl::report {

Image8::Image8(int w, int h, Rgb8 fill) : width(w), height(h), pixels(static_cast<size_t>(w) * h * 3) {
  for (size_t i = 0; i < pixels.size(); i += 3) {
    pixels[i] = fill.r;
    pixels[i + 1] = fill.g;
    pixels[i + 2] = fill.b;
  }
}

Rgb8 Image8::at(int x, int y) const {
  const size_t i = 3 * (static_cast<size_t>(y) * width + x);
  return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

void Image8::set(int x, int y, Rgb8 c) {
  if (!contains(x, y)) return;
  const size_t i = 3 * (static_cast<size_t>(y) * width + x);
  pixels[i] = c.r;
  pixels[i + 1] = c.g;
  pixels[i + 2] = c.b;
}

void Image8::blend(int x, int y, Rgb8 c, double a) {
  if (!contains(x, y) || !(a > 0.0)) return;
  a = std::min(1.0, a);
  const size_t i = 3 * (static_cast<size_t>(y) * width + x);
  const auto mix = [a](std::uint8_t dst, std::uint8_t src) {
    return static_cast<std::uint8_t>(std::lround(dst + (static_cast<double>(src) - dst) * a));
  };
  pixels[i] = mix(pixels[i], c.r);
  pixels[i + 1] = mix(pixels[i + 1], c.g);
  pixels[i + 2] = mix(pixels[i + 2], c.b);
}

void Image8::fill_rect(int x0, int y0, int w, int h, Rgb8 c) {
  for (int y = std::max(0, y0); y < std::min(height, y0 + h); ++y)
    for (int x = std::max(0, x0); x < std::min(width, x0 + w); ++x) set(x, y, c);
}

void Image8::paste(const Image8& src, int x0, int y0) {
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x)
      if (contains(x0 + x, y0 + y)) set(x0 + x, y0 + y, src.at(x, y));
}

}  // namespace fl::report
