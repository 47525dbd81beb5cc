#pragma once
// Plain image buffers for figures: 8-bit sRGB-encoded RGB (what PNGs hold) and linear float RGB
// (what renders and EXRs hold). No I/O here; see png.h and exr.h.
#include <cstdint>
#include <vector>

namespace fl::report {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
};

// 8-bit RGB, row-major, row y = 0 at the top. Pixel (x, y) is pixels[3·(y·width + x) + c].
struct Image8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;

  Image8() = default;
  Image8(int w, int h, Rgb8 fill = {255, 255, 255});
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  Rgb8 at(int x, int y) const;
  void set(int x, int y, Rgb8 c);
  // Source-over blend of colour c with coverage a ∈ [0, 1], in the encoded (display) values.
  void blend(int x, int y, Rgb8 c, double a);
  void fill_rect(int x0, int y0, int w, int h, Rgb8 c);
  // Copies `src` with its top-left corner at (x, y), clipped to this image.
  void paste(const Image8& src, int x, int y);
};

// Linear float RGB, same layout as Image8 (3 floats per pixel).
struct ImageF {
  int width = 0, height = 0;
  std::vector<float> pixels;
};

}  // namespace fl::report
