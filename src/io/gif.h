#pragma once
// Animated GIF files (giflib stays inside gif.cpp).
#include <string>
#include <vector>

#include "io/image.h"

namespace fl::report {

// The frames (all the same size) shown in turn for delay_cs hundredths of a second each, looping
// forever. One global palette of at most 256 colours serves every frame: giflib's median-cut
// quantizer (GifQuantizeBuffer) runs once over all frames together, so a pixel that is the same in
// two frames is the same colour in both and a flip shows only what differs. The same frames give
// the same bytes. std::invalid_argument for no frames or frames of different sizes.
std::string encode_gif(const std::vector<Image8>& frames, int delay_cs);

// A decoded GIF, for tests and tools: each frame's colours (the palette applied) and delay.
struct GifAnimation {
  std::vector<Image8> frames;
  std::vector<int> delays_cs;
  int loop_count = -1;  // NETSCAPE2.0 loop count (0: forever); -1 when the file has none
  int palette_size = 0;
};
// Throws InputError naming `what` when the bytes are not a GIF.
GifAnimation decode_gif(const std::string& bytes, const std::string& what);

}  // namespace fl::report
