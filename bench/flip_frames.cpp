// Writes the frames of an animated flip (FILE.flip.webp or FILE.flip.gif) as PNG files, with
// each frame's delay, for scripts/flip_banding.py and for looking at a flip frame by frame.
//   flip_frames FLIP OUT_PREFIX      writes OUT_PREFIX-0.png, OUT_PREFIX-1.png, ...;
//                                    stdout: one line per frame "INDEX DELAY_MS", then "loop N"
//   flip_frames FLIP OUT.png I,J,... writes frames I, J, ... side by side (8 px apart) as one PNG
#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "draw/png.h"
#include "io/gif.h"
#include "io/webp.h"
#include "util/errors.h"

namespace {

using fl::io::Image8;

// Frames `list` (comma-separated indices) side by side on a white ground, 8 px apart.
Image8 side_by_side(const std::vector<Image8>& frames, const std::string& list) {
  std::vector<size_t> pick;
  std::istringstream in(list);
  for (std::string i; std::getline(in, i, ',');) pick.push_back(std::stoul(i));
  const int gap = 8, w = frames.at(0).width, h = frames.at(0).height;
  Image8 out(static_cast<int>(pick.size()) * (w + gap) - gap, h);
  for (size_t n = 0; n < pick.size(); ++n)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        out.set(static_cast<int>(n) * (w + gap) + x, y, frames.at(pick[n]).at(x, y));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fl::io;
  using namespace fl::draw;
  if (argc != 3 && argc != 4) {
    fmt::print(stderr, "usage: flip_frames FLIP.webp|FLIP.gif OUT_PREFIX | OUT.png I,J,...\n");
    return 2;
  }
  const std::string path = argv[1], prefix = argv[2];
  std::ifstream in(path, std::ios::binary);
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  try {
    std::vector<Image8> frames;
    std::vector<int> delays_ms;
    int loop = 0;
    if (path.ends_with(".gif")) {
      auto gif = decode_gif(bytes, path);
      frames = std::move(gif.frames);
      for (int d : gif.delays_cs) delays_ms.push_back(10 * d);
      loop = gif.loop_count;
    } else {
      auto webp = decode_webp(bytes, path);
      frames = std::move(webp.frames);
      delays_ms = webp.delays_ms;
      loop = webp.loop_count;
    }
    if (argc == 4) {
      write_png_atomic(prefix, side_by_side(frames, argv[3]));
      return 0;
    }
    for (size_t i = 0; i < frames.size(); ++i) {
      write_png_atomic(fmt::format("{}-{}.png", prefix, i), frames[i]);
      fmt::print("{} {}\n", i, delays_ms[i]);
    }
    fmt::print("loop {}\n", loop);
  } catch (const fl::InputError& e) {
    fmt::print(stderr, "flip_frames: {}\n", e.what());
    return 2;
  }
  return 0;
}
