#include "report/font.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <cstdlib>
#include <map>
#include <vector>

#include "spectral/errors.h"

namespace fl::report {
namespace {

// UTF-8 → code points (invalid bytes become U+FFFD).
std::vector<char32_t> decode_utf8(const std::string& s) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + extra >= s.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t cp = extra == 0 ? c : c & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    out.push_back(cp);
    i += extra + 1;
  }
  return out;
}

struct Glyph {
  int width = 0, rows = 0, left = 0, top = 0, advance = 0;  // pixels; top: bitmap top above the baseline
  std::vector<unsigned char> coverage;
};

}  // namespace

struct Font::Impl {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  std::map<std::pair<int, char32_t>, Glyph> cache;

  const Glyph& glyph(char32_t cp, int size_px) {
    const auto key = std::make_pair(size_px, cp);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    Glyph g;
    FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px));
    if (FT_Load_Char(face, cp, FT_LOAD_RENDER | FT_LOAD_TARGET_NORMAL) == 0) {
      const FT_GlyphSlot slot = face->glyph;
      g.width = static_cast<int>(slot->bitmap.width);
      g.rows = static_cast<int>(slot->bitmap.rows);
      g.left = slot->bitmap_left;
      g.top = slot->bitmap_top;
      g.advance = static_cast<int>((slot->advance.x + 32) >> 6);  // 26.6 fixed point, rounded
      g.coverage.resize(static_cast<size_t>(g.width) * g.rows);
      for (int y = 0; y < g.rows; ++y)
        for (int x = 0; x < g.width; ++x)
          g.coverage[static_cast<size_t>(y) * g.width + x] = slot->bitmap.buffer[y * slot->bitmap.pitch + x];
    }
    return cache.emplace(key, std::move(g)).first->second;
  }
};

std::string Font::default_path() {
  if (const char* env = std::getenv("FRESNEL_LAB_FONT"); env && *env) return env;
  return "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
}

Font::Font(const std::string& path) : impl_(std::make_unique<Impl>()) {
  const std::string p = path.empty() ? default_path() : path;
  if (FT_Init_FreeType(&impl_->library) != 0) throw std::runtime_error("FreeType: cannot initialize");
  if (FT_New_Face(impl_->library, p.c_str(), 0, &impl_->face) != 0) {
    FT_Done_FreeType(impl_->library);
    impl_->library = nullptr;
    throw InputError(p, 0, "cannot load the label font (install fonts-dejavu-core or set FRESNEL_LAB_FONT)");
  }
}

Font::~Font() {
  if (impl_ && impl_->face) FT_Done_Face(impl_->face);
  if (impl_ && impl_->library) FT_Done_FreeType(impl_->library);
}

int Font::text_width(const std::string& utf8, int size_px) {
  int w = 0;
  for (char32_t cp : decode_utf8(utf8)) w += impl_->glyph(cp, size_px).advance;
  return w;
}

void Font::draw(Image8& img, int x, int baseline_y, const std::string& utf8, int size_px, Rgb8 colour, Align align) {
  if (align != Align::Left) {
    const int w = text_width(utf8, size_px);
    x -= align == Align::Center ? w / 2 : w;
  }
  for (char32_t cp : decode_utf8(utf8)) {
    const Glyph& g = impl_->glyph(cp, size_px);
    for (int gy = 0; gy < g.rows; ++gy)
      for (int gx = 0; gx < g.width; ++gx) {
        const unsigned char c = g.coverage[static_cast<size_t>(gy) * g.width + gx];
        if (c) img.blend(x + g.left + gx, baseline_y - g.top + gy, colour, c / 255.0);
      }
    x += g.advance;
  }
}

void Font::draw_vertical(Image8& img, int cx, int cy, const std::string& utf8, int size_px, Rgb8 colour) {
  // Render horizontally into a white scratch image as a coverage mask, then turn it.
  const int w = text_width(utf8, size_px) + 2;
  const int h = size_px * 3 / 2;
  Image8 tmp(w, h, {0, 0, 0});
  draw(tmp, 1, size_px, utf8, size_px, {255, 255, 255});
  // Turned 90° counter-clockwise: scratch (x, y) → (y, w − 1 − x).
  const int x0 = cx - h / 2, y0 = cy - w / 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int a = tmp.at(x, y).r;
      if (a) img.blend(x0 + y, y0 + (w - 1 - x), colour, a / 255.0);
    }
}

}  // namespace fl::report
