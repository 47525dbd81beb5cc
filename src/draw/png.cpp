#include "draw/png.h"

#include <cairo.h>

#include <memory>
#include <stdexcept>

#include "draw/drawing.h"
#include "io/writer.h"
#include "util/errors.h"

namespace fl::draw {

std::string encode_png(const io::Image8& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<size_t>(image.width) * image.height * 3)
    throw std::logic_error("encode_png: image size and pixel count disagree");
  Drawing d;
  d.width = image.width;
  d.height = image.height;
  d.add(Picture{0, 0, image});
  return encode_without_text(d, FileType::Png);
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
  io::Image8 img(cairo_image_surface_get_width(s.get()), cairo_image_surface_get_height(s.get()));
  const unsigned char* data = cairo_image_surface_get_data(s.get());
  const int stride = cairo_image_surface_get_stride(s.get());
  for (int y = 0; y < img.height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<size_t>(y) * stride);
    for (int x = 0; x < img.width; ++x)
      img.set(x, y,
              {static_cast<std::uint8_t>(row[x] >> 16), static_cast<std::uint8_t>(row[x] >> 8),
               static_cast<std::uint8_t>(row[x])});
  }
  return img;
}

}  // namespace fl::draw
