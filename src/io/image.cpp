#include "io/image.h"

#include <stdexcept>

namespace fl::io {

Image8::Image8(int w, int h, Rgb8 fill)
    : width(w), height(h), pixels(static_cast<size_t>(w) * h * 3) {
  for (size_t i = 0; i < pixels.size(); i += 3) {
    pixels[i] = fill.r;
    pixels[i + 1] = fill.g;
    pixels[i + 2] = fill.b;
  }
}

Image8::Image8(int w, int h, std::vector<std::uint8_t> codes)
    : width(w), height(h), pixels(std::move(codes)) {
  if (w < 0 || h < 0 || pixels.size() != static_cast<size_t>(w) * h * 3)
    throw std::invalid_argument("Image8: the code count is not 3 × width × height");
}

}  // namespace fl::io
