#include "draw/png.h"

#include <cairo.h>
#include <png.h>

#include <csetjmp>
#include <memory>
#include <stdexcept>

#include "draw/cairo_pixels.h"
#include "io/writer.h"
#include "util/errors.h"

namespace fl::draw {

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  bool failed = false;
  try {
    static_cast<std::string*>(png_get_io_ptr(png))
        ->append(reinterpret_cast<const char*>(data), length);
  } catch (...) {
    failed = true;  // png_error jumps: never from inside the handler
  }
  if (failed) png_error(png, "out of memory");
}
void no_flush(png_structp) {}
// libpng's errors return to encode_png's setjmp, silently (it throws); it has no warnings to
// give for images it is handed whole.
[[noreturn]] void on_error(png_structp png, png_const_charp) {
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

}  // namespace

std::string encode_png(const io::Image8& image) {
  const int width = image.width, height = image.height;
  const auto& rgb = image.pixels;
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<size_t>(width) * height * 3)
    throw std::logic_error("encode_png: image size and pixel count disagree");
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  if (!png) throw std::bad_alloc();
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw std::bad_alloc();
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("PNG encoding failed");
  }
  png_set_write_fn(png, &out, append_bytes, no_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  const size_t row_bytes = static_cast<size_t>(width) * 3;
  for (int y = 0; y < height; ++y)
    png_write_row(png, rgb.data() + static_cast<size_t>(y) * row_bytes);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

void write_png_atomic(const std::string& path, const io::Image8& image) {
  io::write_file_atomic(path, encode_png(image));
}

io::Image8 read_png(const std::string& path) {
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> s(
      cairo_image_surface_create_from_png(path.c_str()), cairo_surface_destroy);
  const cairo_status_t status = cairo_surface_status(s.get());
  if (status != CAIRO_STATUS_SUCCESS)
    throw InputError(path, 0, std::string("not a readable PNG: ") + cairo_status_to_string(status));
  const cairo_format_t format = cairo_image_surface_get_format(s.get());
  if (format != CAIRO_FORMAT_RGB24 && format != CAIRO_FORMAT_ARGB32)
    throw InputError(path, 0, "not an RGB PNG");
  return surface_pixels(s.get());
}

}  // namespace fl::draw
