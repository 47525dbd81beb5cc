#include "io/webp.h"

#include <webp/demux.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <memory>
#include <stdexcept>

#include "util/errors.h"

namespace fl::io {
namespace {

struct EncoderDeleter {
  void operator()(WebPAnimEncoder* e) const { WebPAnimEncoderDelete(e); }
};
struct DecoderDeleter {
  void operator()(WebPAnimDecoder* d) const { WebPAnimDecoderDelete(d); }
};
struct PictureGuard {
  WebPPicture picture;
  ~PictureGuard() { WebPPictureFree(&picture); }
};

void check_frames(const std::vector<Image8>& frames, int delay_ms) {
  if (frames.empty()) throw std::invalid_argument("encode_webp: no frames");
  if (delay_ms < 1) throw std::invalid_argument("encode_webp: delay under 1 ms");
  for (const auto& f : frames)
    if (f.width != frames[0].width || f.height != frames[0].height || f.width <= 0 || f.height <= 0)
      throw std::invalid_argument("encode_webp: frames differ in size");
}

// Lossless, single-threaded, a fixed effort: nothing depends on the machine or the clock.
WebPConfig lossless_config() {
  WebPConfig config;
  if (!WebPConfigInit(&config)) throw std::runtime_error("WebP encoding failed: library version");
  config.lossless = 1;
  config.exact = 1;
  config.quality = 75;  // lossless effort: compression, not fidelity
  config.method = 4;
  config.thread_level = 0;
  return config;
}

void add_frame(WebPAnimEncoder* enc, const Image8& frame, int timestamp_ms,
               const WebPConfig& config) {
  PictureGuard g;
  if (!WebPPictureInit(&g.picture)) throw std::runtime_error("WebP encoding failed: picture");
  g.picture.use_argb = 1;
  g.picture.width = frame.width;
  g.picture.height = frame.height;
  if (!WebPPictureImportRGB(&g.picture, frame.pixels.data(), 3 * frame.width))
    throw std::bad_alloc();
  if (!WebPAnimEncoderAdd(enc, &g.picture, timestamp_ms, &config))
    throw std::runtime_error(std::string("WebP encoding failed: ") + WebPAnimEncoderGetError(enc));
}

}  // namespace

std::string encode_webp(const std::vector<Image8>& frames, int delay_ms) {
  check_frames(frames, delay_ms);
  WebPAnimEncoderOptions options;
  if (!WebPAnimEncoderOptionsInit(&options))
    throw std::runtime_error("WebP encoding failed: library version");
  options.anim_params.loop_count = 0;  // forever
  options.anim_params.bgcolor = 0xff000000;
  options.minimize_size = 0;
  options.allow_mixed = 0;  // every frame lossless
  std::unique_ptr<WebPAnimEncoder, EncoderDeleter> enc(
      WebPAnimEncoderNew(frames[0].width, frames[0].height, &options));
  if (!enc) throw std::bad_alloc();
  const WebPConfig config = lossless_config();
  int t = 0;
  for (const auto& f : frames) {
    add_frame(enc.get(), f, t, config);
    t += delay_ms;
  }
  // The end time gives the last frame its duration.
  if (!WebPAnimEncoderAdd(enc.get(), nullptr, t, nullptr))
    throw std::runtime_error(std::string("WebP encoding failed: ") +
                             WebPAnimEncoderGetError(enc.get()));
  WebPData data;
  WebPDataInit(&data);
  if (!WebPAnimEncoderAssemble(enc.get(), &data))
    throw std::runtime_error(std::string("WebP encoding failed: ") +
                             WebPAnimEncoderGetError(enc.get()));
  std::string out(reinterpret_cast<const char*>(data.bytes), data.size);
  WebPDataClear(&data);
  return out;
}

WebpAnimation decode_webp(const std::string& bytes, const std::string& what) {
  const WebPData data{reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  if (!WebPAnimDecoderOptionsInit(&options))
    throw std::runtime_error("WebP decoding failed: library version");
  options.color_mode = MODE_RGBA;
  options.use_threads = 0;
  std::unique_ptr<WebPAnimDecoder, DecoderDeleter> dec(WebPAnimDecoderNew(&data, &options));
  if (!dec) throw InputError(what, 0, "not a WebP");
  WebPAnimInfo info;
  if (!WebPAnimDecoderGetInfo(dec.get(), &info)) throw InputError(what, 0, "not a readable WebP");
  WebpAnimation a;
  a.loop_count = static_cast<int>(info.loop_count);
  const int w = static_cast<int>(info.canvas_width), h = static_cast<int>(info.canvas_height);
  int previous_ms = 0;
  while (WebPAnimDecoderHasMoreFrames(dec.get())) {
    uint8_t* rgba = nullptr;
    int end_ms = 0;  // the time this frame ends
    if (!WebPAnimDecoderGetNext(dec.get(), &rgba, &end_ms))
      throw InputError(what, 0, "not a readable WebP: frame " + std::to_string(a.frames.size()));
    Image8 frame(w, h);
    for (size_t k = 0; k < static_cast<size_t>(w) * h; ++k)
      for (int c = 0; c < 3; ++c) frame.pixels[3 * k + c] = rgba[4 * k + c];
    a.frames.push_back(std::move(frame));
    a.delays_ms.push_back(end_ms - previous_ms);
    previous_ms = end_ms;
  }
  return a;
}

}  // namespace fl::io
