#pragma once
// 8-bit sRGB-encoded RGB images (what PNGs hold and figures paint). No I/O here; see png.h.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::io {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

// Row-major, row y = 0 at the top. Pixel (x, y) is pixels[3·(y·width + x) + c].
struct Image8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;

  Image8() = default;
  Image8(int w, int h, Rgb8 fill = {255, 255, 255});
  // Takes 3·w·h codes (std::invalid_argument otherwise).
  Image8(int w, int h, std::vector<std::uint8_t> codes);
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  Rgb8 at(int x, int y) const {
    const size_t i = 3 * (static_cast<size_t>(y) * width + x);
    return {pixels[i], pixels[i + 1], pixels[i + 2]};
  }
  void set(int x, int y, Rgb8 c) {  // ignored outside the image
    if (!contains(x, y)) return;
    const size_t i = 3 * (static_cast<size_t>(y) * width + x);
    pixels[i] = c.r;
    pixels[i + 1] = c.g;
    pixels[i + 2] = c.b;
  }
};

}  // namespace fl::io
