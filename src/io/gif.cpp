#include "io/gif.h"

#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "util/errors.h"

namespace fl::io {
namespace {

int append_bytes(GifFileType* gif, const GifByteType* data, int length) {
  static_cast<std::string*>(gif->UserData)
      ->append(reinterpret_cast<const char*>(data), static_cast<size_t>(length));
  return length;
}

void check(int status, GifFileType* gif, const char* step) {
  if (status == GIF_OK) return;
  throw std::runtime_error(std::string("GIF encoding failed at ") + step + ": " +
                           GifErrorString(gif->Error));
}

struct MapDeleter {
  void operator()(ColorMapObject* m) const { GifFreeMapObject(m); }
};
using Palette = std::unique_ptr<ColorMapObject, MapDeleter>;

// The nearest palette entry (squared distance of the codes, the lowest index on a tie) per 24-bit
// colour, remembered for one palette.
class Nearest {
 public:
  explicit Nearest(const ColorMapObject& palette) : palette_(palette), index_(1u << 24, -1) {}
  int operator()(int r, int g, int b) {
    std::int16_t& i = index_[(static_cast<size_t>(r) << 16) | (g << 8) | b];
    if (i >= 0) return i;
    int best = 0, best_d = 1 << 30;
    for (int k = 0; k < palette_.ColorCount; ++k) {
      const GifColorType& c = palette_.Colors[k];
      const int d =
          (c.Red - r) * (c.Red - r) + (c.Green - g) * (c.Green - g) + (c.Blue - b) * (c.Blue - b);
      if (d < best_d) best = k, best_d = d;
    }
    return i = static_cast<std::int16_t>(best);
  }

 private:
  const ColorMapObject& palette_;
  std::vector<std::int16_t> index_;
};

// Two rounds of Lloyd's k-means on the palette: each entry becomes the mean of the pixels nearest
// to it (an entry no pixel is nearest to stays). Moves giflib's entries, which it computes from
// colours binned to 5 bits per channel, to the frame's own colours.
void refine(const Image8& frame, ColorMapObject& palette) {
  for (int round = 0; round < 2; ++round) {
    std::vector<std::array<std::uint64_t, 4>> sum(static_cast<size_t>(palette.ColorCount));
    Nearest nearest(palette);
    for (size_t k = 0; 3 * k < frame.pixels.size(); ++k) {
      const std::uint8_t* p = &frame.pixels[3 * k];
      auto& s = sum[static_cast<size_t>(nearest(p[0], p[1], p[2]))];
      s[0] += p[0], s[1] += p[1], s[2] += p[2], s[3] += 1;
    }
    for (int i = 0; i < palette.ColorCount; ++i) {
      const auto& s = sum[static_cast<size_t>(i)];
      if (s[3] == 0) continue;
      const auto mean = [&](int c) {
        return static_cast<GifByteType>((2 * s[c] + s[3]) / (2 * s[3]));
      };
      palette.Colors[i] = {mean(0), mean(1), mean(2)};
    }
  }
}

// The frame's own palette: giflib's median-cut quantizer (GifQuantizeBuffer) over its pixels,
// refined.
Palette frame_palette(const Image8& frame) {
  const size_t n = static_cast<size_t>(frame.width) * frame.height;
  std::vector<GifByteType> r(n), g(n), b(n), unused(n);
  for (size_t k = 0; k < n; ++k)
    r[k] = frame.pixels[3 * k], g[k] = frame.pixels[3 * k + 1], b[k] = frame.pixels[3 * k + 2];
  Palette palette(GifMakeMapObject(256, nullptr));
  if (!palette) throw std::bad_alloc();
  int colours = 256;
  if (GifQuantizeBuffer(static_cast<unsigned>(frame.width), static_cast<unsigned>(frame.height),
                        &colours, r.data(), g.data(), b.data(), unused.data(),
                        palette->Colors) != GIF_OK)
    throw std::runtime_error("GIF encoding failed: colour quantization");
  // Entries giflib left unused repeat entry 0: never nearest (a tie goes to the lowest index).
  for (int i = colours; i < palette->ColorCount; ++i) palette->Colors[i] = palette->Colors[0];
  refine(frame, *palette);
  return palette;
}

// The frame's pixels as indices into `palette` by Floyd–Steinberg error diffusion (Floyd &
// Steinberg 1976: 7/16 of a pixel's error to the right, 3/16, 5/16 and 1/16 to the row below),
// left to right on every row, in integer sixteenths of a code: deterministic on every machine.
std::vector<GifByteType> dither(const Image8& frame, const ColorMapObject& palette) {
  const int w = frame.width, h = frame.height;
  std::vector<GifByteType> indices(static_cast<size_t>(w) * h);
  std::vector<int> err(3 * static_cast<size_t>(w + 2)), below(err.size());  // x + 1
  Nearest nearest(palette);
  for (int y = 0; y < h; ++y) {
    std::fill(below.begin(), below.end(), 0);
    for (int x = 0; x < w; ++x) {
      const size_t k = static_cast<size_t>(y) * w + x, e = 3 * static_cast<size_t>(x + 1);
      int want[3], code[3];
      for (int c = 0; c < 3; ++c) {
        want[c] = std::clamp(16 * frame.pixels[3 * k + c] + err[e + c], 0, 16 * 255);
        code[c] = (want[c] + 8) / 16;
      }
      const int i = nearest(code[0], code[1], code[2]);
      indices[k] = static_cast<GifByteType>(i);
      const GifColorType& got = palette.Colors[i];
      const int have[3] = {got.Red, got.Green, got.Blue};
      for (int c = 0; c < 3; ++c) {
        const int q = want[c] - 16 * have[c];
        err[e + 3 + c] += q * 7 / 16;
        below[e - 3 + c] += q * 3 / 16;
        below[e + c] += q * 5 / 16;
        below[e + 3 + c] += q / 16;
      }
    }
    std::swap(err, below);
  }
  return indices;
}

// The NETSCAPE2.0 application extension: loop forever.
void put_loop_forever(GifFileType* gif) {
  static const GifByteType kApp[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  static const GifByteType kLoop[] = {1, 0, 0};  // sub-block 1, loop count 0 (little endian)
  check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), gif, "loop extension");
  check(EGifPutExtensionBlock(gif, sizeof kApp, kApp), gif, "loop extension");
  check(EGifPutExtensionBlock(gif, sizeof kLoop, kLoop), gif, "loop extension");
  check(EGifPutExtensionTrailer(gif), gif, "loop extension");
}

void put_frames(GifFileType* gif, const std::vector<Image8>& frames, int delay_cs) {
  const int w = frames[0].width, h = frames[0].height;
  GraphicsControlBlock gcb{};
  gcb.DisposalMode = DISPOSE_DO_NOT;
  gcb.DelayTime = delay_cs;
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType ext[4];
  const size_t ext_len = EGifGCBToExtension(&gcb, ext);
  for (const auto& frame : frames) {
    const Palette palette = frame_palette(frame);
    auto indices = dither(frame, *palette);
    check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(ext_len), ext), gif,
          "frame delay");
    check(EGifPutImageDesc(gif, 0, 0, w, h, false, palette.get()), gif, "frame");
    for (int y = 0; y < h; ++y)
      check(EGifPutLine(gif, &indices[static_cast<size_t>(y) * w], w), gif, "frame pixels");
  }
}

}  // namespace

std::string encode_gif(const std::vector<Image8>& frames, int delay_cs) {
  if (frames.empty()) throw std::invalid_argument("encode_gif: no frames");
  for (const auto& f : frames)
    if (f.width != frames[0].width || f.height != frames[0].height || f.width <= 0 || f.height <= 0)
      throw std::invalid_argument("encode_gif: frames differ in size");
  std::string out;
  int error = 0;
  GifFileType* gif = EGifOpen(&out, append_bytes, &error);
  if (!gif) throw std::runtime_error(std::string("GIF encoding failed: ") + GifErrorString(error));
  try {
    EGifSetGifVersion(gif, true);
    // No global colour map: every frame carries its own.
    check(EGifPutScreenDesc(gif, frames[0].width, frames[0].height, 8, 0, nullptr), gif, "screen");
    put_loop_forever(gif);
    put_frames(gif, frames, delay_cs);
  } catch (...) {
    EGifCloseFile(gif, &error);
    throw;
  }
  if (EGifCloseFile(gif, &error) != GIF_OK)
    throw std::runtime_error(std::string("GIF encoding failed: ") + GifErrorString(error));
  return out;
}

namespace {

struct ReadState {
  const std::string* bytes;
  size_t position = 0;
};

int read_bytes(GifFileType* gif, GifByteType* data, int length) {
  auto* s = static_cast<ReadState*>(gif->UserData);
  const size_t n = std::min(static_cast<size_t>(length), s->bytes->size() - s->position);
  std::memcpy(data, s->bytes->data() + s->position, n);
  s->position += n;
  return static_cast<int>(n);
}

// The frame's colours, its delay and (from its extension blocks) the loop count.
Image8 frame_colours(const GifFileType* gif, const SavedImage& img) {
  const ColorMapObject* map = img.ImageDesc.ColorMap ? img.ImageDesc.ColorMap : gif->SColorMap;
  Image8 out(img.ImageDesc.Width, img.ImageDesc.Height);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const GifColorType c =
          map->Colors[img.RasterBits[static_cast<size_t>(y) * out.width + x] % map->ColorCount];
      out.set(x, y, {c.Red, c.Green, c.Blue});
    }
  return out;
}

}  // namespace

GifAnimation decode_gif(const std::string& bytes, const std::string& what) {
  ReadState state{&bytes};
  int error = 0;
  GifFileType* gif = DGifOpen(&state, read_bytes, &error);
  if (!gif) throw InputError(what, 0, std::string("not a GIF: ") + GifErrorString(error));
  GifAnimation a;
  bool ok = DGifSlurp(gif) == GIF_OK;
  for (int i = 0; ok && i < gif->ImageCount; ++i) {
    const SavedImage& img = gif->SavedImages[i];
    if (!(ok = img.ImageDesc.ColorMap || gif->SColorMap)) break;  // a frame without colours
    a.local_palette_sizes.push_back(img.ImageDesc.ColorMap ? img.ImageDesc.ColorMap->ColorCount
                                                           : 0);
    a.frames.push_back(frame_colours(gif, img));
    GraphicsControlBlock gcb{};
    a.delays_cs.push_back(DGifSavedExtensionToGCB(gif, i, &gcb) == GIF_OK ? gcb.DelayTime : 0);
    for (int e = 0; e + 1 < img.ExtensionBlockCount; ++e)
      if (img.ExtensionBlocks[e].Function == APPLICATION_EXT_FUNC_CODE &&
          img.ExtensionBlocks[e].ByteCount == 11 &&
          std::memcmp(img.ExtensionBlocks[e].Bytes, "NETSCAPE2.0", 11) == 0 &&
          img.ExtensionBlocks[e + 1].ByteCount >= 3)
        a.loop_count =
            img.ExtensionBlocks[e + 1].Bytes[1] | (img.ExtensionBlocks[e + 1].Bytes[2] << 8);
  }
  if (ok && gif->SColorMap) a.global_palette_size = gif->SColorMap->ColorCount;
  const std::string message =
      ok ? "" : (gif->Error ? GifErrorString(gif->Error) : "a frame has no colour map");
  DGifCloseFile(gif, &error);
  if (!ok) throw InputError(what, 0, "not a readable GIF: " + message);
  return a;
}

}  // namespace fl::io
