// The flip files of `render --compare`: animated WebP (lossless, checked against the RIFF chunks
// the WebP container specification defines), the dithered GIF with a palette per frame (against
// giflib's own undithered quantization), and the difference frame's arithmetic.
#include <gif_lib.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <variant>

#include "draw/flip.h"
#include "io/gif.h"
#include "io/webp.h"
#include "util/errors.h"

namespace fl {
namespace {

using io::Image8;
using io::Rgb8;

// A frame of w × h pixels that every channel varies over (a fixed linear congruential sequence
// mixed with gradients), so that a lossy or palette encoding would change codes.
Image8 busy_frame(int w, int h, std::uint32_t seed) {
  Image8 f(w, h);
  std::uint32_t s = seed;
  for (auto& c : f.pixels) {
    s = s * 1664525u + 1013904223u;
    c = static_cast<std::uint8_t>(s >> 24);
  }
  return f;
}

std::uint32_t le(const std::string& b, size_t at, int bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= std::uint32_t(std::uint8_t(b[at + i])) << (8 * i);
  return v;
}

// The payload offsets of every chunk `id` at the top level of the RIFF container (WebP container
// specification: "RIFF" size "WEBP", then chunks of a FourCC, a 32-bit little-endian size and the
// payload padded to an even length).
std::vector<size_t> chunks(const std::string& b, const std::string& id) {
  std::vector<size_t> at;
  for (size_t p = 12; p + 8 <= b.size(); p += 8 + ((le(b, p + 4, 4) + 1) & ~1u))
    if (b.compare(p, 4, id) == 0) at.push_back(p + 8);
  return at;
}

TEST(Webp, LosslessFramesLoopForeverDelaysAndSameBytes) {
  const Image8 a = busy_frame(37, 23, 1), b = busy_frame(37, 23, 2);
  Image8 c = a;
  c.set(5, 7, {1, 2, 3});  // differs from a in one pixel
  const std::vector<Image8> frames{a, b, c, a};
  const auto bytes = io::encode_webp(frames, 900);
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(bytes.substr(0, 4), "RIFF");
  EXPECT_EQ(bytes.substr(8, 4), "WEBP");
  EXPECT_EQ(le(bytes, 4, 4) + 8, bytes.size());
  const auto anim = chunks(bytes, "ANIM"), anmf = chunks(bytes, "ANMF");
  ASSERT_EQ(anim.size(), 1u);
  EXPECT_EQ(le(bytes, anim[0] + 4, 2), 0u);  // loop count 0: forever
  ASSERT_EQ(anmf.size(), 4u);
  for (size_t f : anmf) {
    EXPECT_EQ(le(bytes, f + 12, 3), 900u);           // frame duration, ms
    EXPECT_EQ(bytes.compare(f + 16, 4, "VP8L"), 0);  // lossless bitstream
  }
  const auto decoded = io::decode_webp(bytes, "flip.webp");
  ASSERT_EQ(decoded.frames.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(decoded.frames[i].width, 37);
    EXPECT_EQ(decoded.frames[i].pixels, frames[i].pixels) << "frame " << i;
  }
  EXPECT_EQ(decoded.delays_ms, (std::vector<int>{900, 900, 900, 900}));
  EXPECT_EQ(decoded.loop_count, 0);
  EXPECT_EQ(io::encode_webp(frames, 900), bytes);  // deterministic
  EXPECT_THROW(io::encode_webp({a, Image8(10, 10)}, 900), std::invalid_argument);
  EXPECT_THROW(io::encode_webp({}, 900), std::invalid_argument);
  EXPECT_THROW(io::decode_webp("RIFF0000WEBPjunk", "x.webp"), InputError);
}

// The difference frame's arithmetic: 128 + 32 × 255 × (model − truth) per channel of the
// display-encoded floats, rounded and clamped; the panels' 2 × 2 means rounded half up. A
// difference under half a code, which rounding both images to codes would show as 0 or ±32, stays
// near mid grey.
TEST(FlipFrames, SignedDifferenceAndHalfSize) {
  const auto values = [](std::vector<float> rgb) { return draw::DisplayValues{2, 2, rgb}; };
  const float t = 0.5f, code = 1.0f / 255;
  const auto truth = values(std::vector<float>(12, t));
  const auto model = values({t + 3 * code, t, t - 10 * code,       // +3, 0, −10 codes
                             t + code, t - code, t,                // ±1 code
                             t + 0.2f * code, t - 0.3f * code, t,  // under half a code
                             1.0f, 0.0f, t + 16 * code});          // clips
  const Image8 d = draw::signed_difference(truth, model);
  EXPECT_EQ(d.at(0, 0), (Rgb8{224, 128, 0}));
  EXPECT_EQ(d.at(1, 0), (Rgb8{160, 96, 128}));
  EXPECT_EQ(d.at(0, 1), (Rgb8{134, 118, 128}));  // 128 + 6.4 and 128 − 9.6, rounded
  EXPECT_EQ(d.at(1, 1), (Rgb8{255, 0, 255}));
  const Image8 h = draw::half_size(d);
  ASSERT_EQ(h.width, 1);
  EXPECT_EQ(h.at(0, 0), (Rgb8{(224 + 160 + 134 + 255 + 2) / 4, (128 + 96 + 118 + 0 + 2) / 4,
                              (0 + 128 + 128 + 255 + 2) / 4}));
  EXPECT_THROW(draw::signed_difference(truth, draw::DisplayValues{3, 2, {}}),
               std::invalid_argument);
}

// Captions stay legible at every frame size: at the GIF's 256 px as at 512 px, every text of a
// difference frame and of a model frame is at least kFlipMinTextPx and, measured in the font, fits
// inside the frame (a long model name gives way to a shorter wording rather than to 5 px text).
TEST(FlipFrames, CaptionsLegibleAtEverySize) {
  const draw::LabelFont font;
  for (const int size : {256, 512}) {
    const draw::DisplayValues grey{size, size, std::vector<float>(3 * size * size, 0.5f)};
    const std::vector<double> de(static_cast<size_t>(size) * size, 0.5);
    const std::string name = "generalized_schlick";
    const auto diff = draw::flip_difference_drawing(grey, grey, de, 2.0, name,
                                                    name + " (rendered): difference", font);
    const auto frame = draw::flip_frame_drawing(Image8(size, size), name + " (rendered)",
                                                "ΔE2000 mean 0.42, max 1.87", font);
    int texts = 0;
    for (const auto* d : {&diff, &frame})
      for (const auto& shape : d->shapes)
        if (const auto* t = std::get_if<draw::Text>(&shape)) {
          ++texts;
          EXPECT_GE(t->size_px, draw::kFlipMinTextPx) << size << ": " << t->utf8;
          const double w = draw::text_width_px(t->utf8, t->size_px, font);
          const double left = t->align == draw::Align::Left    ? t->x
                              : t->align == draw::Align::Right ? t->x - w
                                                               : t->x - w / 2;
          EXPECT_GE(left, 0) << size << ": " << t->utf8;
          EXPECT_LE(left + w, size) << size << ": " << t->utf8;
        }
    EXPECT_EQ(texts, 12) << size;  // 2 band lines + 2 × (caption + 3 ramp labels); 2 band lines
  }
}

// A sky: a smooth two-dimensional gradient from warm grey at the bottom to blue at the top, with
// thousands of colours (more than a palette holds), codes rounded from exact linear ramps.
Image8 sky(int w, int h) {
  Image8 f(w, h);
  const auto code = [](double v) { return static_cast<std::uint8_t>(std::lround(v)); };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u = x / (w - 1.0), v = y / (h - 1.0);
      f.set(x, y, {code(90 + 110 * v + 20 * u), code(120 + 90 * v), code(240 - 60 * v + 10 * u)});
    }
  return f;
}

// The largest error of an n × n block's mean colour (any channel, codes) of `got` against `want`.
double block_mean_error(const Image8& got, const Image8& want, int n) {
  double worst = 0;
  for (int y = 0; y + n <= want.height; y += n)
    for (int x = 0; x + n <= want.width; x += n)
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            const size_t k = 3 * (static_cast<size_t>(y + j) * want.width + x + i) + c;
            sum += double(got.pixels[k]) - double(want.pixels[k]);
          }
        worst = std::max(worst, std::abs(sum) / (n * n));
      }
  return worst;
}

// The frames stacked top to bottom, as one image.
Image8 stacked(const Image8& a, const Image8& b) {
  std::vector<std::uint8_t> codes(a.pixels);
  codes.insert(codes.end(), b.pixels.begin(), b.pixels.end());
  return Image8(a.width, a.height + b.height, std::move(codes));
}

// giflib's quantizer without dithering: every pixel its median-cut box's colour.
Image8 undithered(const Image8& f) {
  const size_t n = static_cast<size_t>(f.width) * f.height;
  std::vector<GifByteType> r(n), g(n), b(n), idx(n);
  for (size_t k = 0; k < n; ++k)
    r[k] = f.pixels[3 * k], g[k] = f.pixels[3 * k + 1], b[k] = f.pixels[3 * k + 2];
  std::vector<GifColorType> map(256);
  int colours = 256;
  EXPECT_EQ(GifQuantizeBuffer(f.width, f.height, &colours, r.data(), g.data(), b.data(), idx.data(),
                              map.data()),
            GIF_OK);
  Image8 out(f.width, f.height);
  for (size_t k = 0; k < n; ++k)
    out.pixels[3 * k] = map[idx[k]].Red, out.pixels[3 * k + 1] = map[idx[k]].Green,
                   out.pixels[3 * k + 2] = map[idx[k]].Blue;
  return out;
}

// A 256-colour palette over a sky of thousands of colours is a few codes apart per channel:
// dithered, an 8 × 8 block's mean stays within 4 codes (under one ΔE2000 at sky tones); a band is a
// step of more than 16 codes, which a shared palette leaves over a smooth frame.
constexpr double kDitheredBlockCodes = 4.0, kBandedBlockCodes = 16.0;

TEST(Gif, PalettePerFrameDitheredKeepsLocalMeans) {
  const Image8 smooth = sky(256, 256), busy = busy_frame(256, 256, 3);
  const auto bytes = io::encode_gif({smooth, busy}, 90);
  const auto gif = io::decode_gif(bytes, "flip.gif");
  ASSERT_EQ(gif.frames.size(), 2u);
  EXPECT_EQ(gif.delays_cs, (std::vector<int>{90, 90}));
  EXPECT_EQ(gif.loop_count, 0);
  EXPECT_EQ(gif.global_palette_size, 0);
  ASSERT_EQ(gif.local_palette_sizes.size(), 2u);
  for (int size : gif.local_palette_sizes) EXPECT_EQ(size, 256);
  const double dithered = block_mean_error(gif.frames[0], smooth, 8);
  const double own = block_mean_error(undithered(smooth), smooth, 8);
  Image8 shared = undithered(stacked(smooth, busy));
  shared.height = smooth.height, shared.pixels.resize(smooth.pixels.size());
  const double global = block_mean_error(shared, smooth, 8);
  // Floyd–Steinberg keeps every 8 × 8 block's mean within kDitheredBlockCodes of the sky's; the
  // same palette without dithering misses by more, and one palette shared with a busy frame (the
  // quantization of both frames together) bands by more than kBandedBlockCodes.
  EXPECT_LT(dithered, kDitheredBlockCodes);
  EXPECT_GT(own, dithered);
  EXPECT_GT(global, kBandedBlockCodes);
  EXPECT_EQ(io::encode_gif({smooth, busy}, 90), bytes);  // deterministic
  EXPECT_THROW(io::decode_gif("not a gif", "x.gif"), InputError);
}

}  // namespace
}  // namespace fl
