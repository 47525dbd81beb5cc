#include "io/gif.h"

#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "util/errors.h"

namespace fl::report {
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

// Every frame's pixels as palette indices (frame after frame), with the shared palette.
std::vector<GifByteType> quantize(const std::vector<Image8>& frames, ColorMapObject*& palette) {
  const size_t per_frame = static_cast<size_t>(frames[0].width) * frames[0].height;
  const size_t n = per_frame * frames.size();
  std::vector<GifByteType> r(n), g(n), b(n), indices(n);
  for (size_t f = 0; f < frames.size(); ++f)
    for (size_t k = 0; k < per_frame; ++k) {
      r[f * per_frame + k] = frames[f].pixels[3 * k];
      g[f * per_frame + k] = frames[f].pixels[3 * k + 1];
      b[f * per_frame + k] = frames[f].pixels[3 * k + 2];
    }
  int colours = 256;
  palette = GifMakeMapObject(256, nullptr);
  if (!palette) throw std::bad_alloc();
  if (GifQuantizeBuffer(static_cast<unsigned>(frames[0].width),
                        static_cast<unsigned>(per_frame / frames[0].width * frames.size()),
                        &colours, r.data(), g.data(), b.data(), indices.data(),
                        palette->Colors) != GIF_OK) {
    GifFreeMapObject(palette);
    throw std::runtime_error("GIF encoding failed: colour quantization");
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

void put_frames(GifFileType* gif, const std::vector<Image8>& frames,
                const std::vector<GifByteType>& indices, int delay_cs) {
  const int w = frames[0].width, h = frames[0].height;
  GraphicsControlBlock gcb{};
  gcb.DisposalMode = DISPOSE_DO_NOT;
  gcb.DelayTime = delay_cs;
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType ext[4];
  const size_t ext_len = EGifGCBToExtension(&gcb, ext);
  std::vector<GifByteType> row(static_cast<size_t>(w));
  for (size_t f = 0; f < frames.size(); ++f) {
    check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(ext_len), ext), gif,
          "frame delay");
    check(EGifPutImageDesc(gif, 0, 0, w, h, false, nullptr), gif, "frame");
    for (int y = 0; y < h; ++y) {
      std::memcpy(row.data(), &indices[(f * h + y) * w], row.size());
      check(EGifPutLine(gif, row.data(), w), gif, "frame pixels");
    }
  }
}

}  // namespace

std::string encode_gif(const std::vector<Image8>& frames, int delay_cs) {
  if (frames.empty()) throw std::invalid_argument("encode_gif: no frames");
  for (const auto& f : frames)
    if (f.width != frames[0].width || f.height != frames[0].height || f.width <= 0 || f.height <= 0)
      throw std::invalid_argument("encode_gif: frames differ in size");
  ColorMapObject* palette = nullptr;
  const auto indices = quantize(frames, palette);
  std::string out;
  int error = 0;
  GifFileType* gif = EGifOpen(&out, append_bytes, &error);
  if (!gif) {
    GifFreeMapObject(palette);
    throw std::runtime_error(std::string("GIF encoding failed: ") + GifErrorString(error));
  }
  try {
    EGifSetGifVersion(gif, true);
    check(EGifPutScreenDesc(gif, frames[0].width, frames[0].height, 8, 0, palette), gif, "screen");
    put_loop_forever(gif);
    put_frames(gif, frames, indices, delay_cs);
  } catch (...) {
    GifFreeMapObject(palette);
    EGifCloseFile(gif, &error);
    throw;
  }
  GifFreeMapObject(palette);
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
  const bool ok = DGifSlurp(gif) == GIF_OK && gif->SColorMap;
  for (int i = 0; ok && i < gif->ImageCount; ++i) {
    const SavedImage& img = gif->SavedImages[i];
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
  if (ok) a.palette_size = gif->SColorMap->ColorCount;
  const std::string message = ok ? "" : GifErrorString(gif->Error);
  DGifCloseFile(gif, &error);
  if (!ok) throw InputError(what, 0, "not a readable GIF: " + message);
  return a;
}

}  // namespace fl::report
