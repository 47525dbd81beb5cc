// Writes the frames of an animated flip (FILE.flip.webp or FILE.flip.gif) as PNG files, with
// each frame's delay, for scripts/flip_banding.py and for looking at a flip frame by frame.
//   flip_frames FLIP OUT_PREFIX      writes OUT_PREFIX-0.png, OUT_PREFIX-1.png, ...;
//                                    stdout: one line per frame "INDEX DELAY_MS", then "loop N"
#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <string>

#include "draw/png.h"
#include "io/gif.h"
#include "io/webp.h"
#include "util/errors.h"

int main(int argc, char** argv) {
  using namespace fl::report;
  if (argc != 3) {
    fmt::print(stderr, "usage: flip_frames FLIP.webp|FLIP.gif OUT_PREFIX\n");
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
