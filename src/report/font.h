#pragma once
// Text for figure labels: DejaVu Sans (Debian's fonts-dejavu-core) rendered by FreeType with
// greyscale antialiasing. FreeType stays inside font.cpp. A Font is not shared between threads:
// each figure (or thread) makes its own.
#include <memory>
#include <string>

#include "report/image.h"

namespace fl::report {

enum class Align { Left, Center, Right };

class Font {
 public:
  // `path` empty: $FRESNEL_LAB_FONT, else /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf.
  // Throws InputError when the font file cannot be loaded.
  explicit Font(const std::string& path = "");
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  // Advance width of `utf8` in pixels at `size_px` (the em size).
  int text_width(const std::string& utf8, int size_px);
  // Draws `utf8` with its baseline at y and its left / centre / right at x.
  void draw(Image8& img, int x, int baseline_y, const std::string& utf8, int size_px, Rgb8 colour,
            Align align = Align::Left);
  // The same text turned 90° counter-clockwise (reading upwards), centred on (cx, cy).
  void draw_vertical(Image8& img, int cx, int cy, const std::string& utf8, int size_px, Rgb8 colour);

  static std::string default_path();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl::report
