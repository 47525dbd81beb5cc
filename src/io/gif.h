#pragma once
// Animated GIF files (giflib stays inside gif.cpp).
#include <string>
#include <vector>

#include "io/image.h"

namespace fl::io {

// The frames (all the same size) shown in turn for delay_cs hundredths of a second each, looping
// forever. Every frame has its own local colour map of at most 256 colours, giflib's median-cut
// quantizer (GifQuantizeBuffer) over that frame's pixels alone, and its pixels are mapped to it by
// Floyd–Steinberg error diffusion, so a smooth gradient keeps its local mean colour instead of
// banding (at the cost of a fine noise, and of frames that differ where the images do not). The
// file has no global colour map. The same frames give the same bytes. std::invalid_argument for no
// frames or frames of different sizes.
std::string encode_gif(const std::vector<Image8>& frames, int delay_cs);

// A decoded GIF, for tests and tools: each frame's colours (the palette applied) and delay.
struct GifAnimation {
  std::vector<Image8> frames;
  std::vector<int> delays_cs;
  int loop_count = -1;  // NETSCAPE2.0 loop count (0: forever); -1 when the file has none
  std::vector<int> local_palette_sizes;  // per frame; 0 when it uses the global colour map
  int global_palette_size = 0;           // 0: none
};
// Throws InputError naming `what` when the bytes are not a GIF.
GifAnimation decode_gif(const std::string& bytes, const std::string& what);

}  // namespace fl::io
