#pragma once
// Animated WebP files (libwebp, libwebpmux and libwebpdemux stay inside webp.cpp).
#include <string>
#include <vector>

#include "io/image.h"

namespace fl::io {

// The frames (all the same size) shown in turn for delay_ms milliseconds each, looping forever,
// encoded losslessly by libwebp's WebPAnimEncoder: every frame decodes to exactly its codes. The
// encoder stores a frame as the rectangle that changed since the previous one; two equal
// consecutive frames become one frame shown twice as long. The file holds no time stamp, metadata
// or random choice: the same frames give the same bytes. std::invalid_argument for no frames,
// frames of different sizes or a delay under 1 ms; std::runtime_error if libwebp fails.
std::string encode_webp(const std::vector<Image8>& frames, int delay_ms);

// A decoded animated WebP, for tests and tools: each frame's colours as shown (the canvas after
// the frame is drawn), how long it stays, and the loop count (0: forever).
struct WebpAnimation {
  std::vector<Image8> frames;
  std::vector<int> delays_ms;
  int loop_count = 0;
};
// Throws InputError naming `what` when the bytes are not an animated (or still) WebP.
WebpAnimation decode_webp(const std::string& bytes, const std::string& what);

}  // namespace fl::io
