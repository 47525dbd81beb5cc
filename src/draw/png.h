#pragma once
// PNG files of plain images. Written through the one drawing renderer (drawing.h: the image painted
// unscaled onto Cairo's image surface, then Cairo's PNG writer): 8-bit RGB, no time or text chunks,
// so the same pixels give the same bytes.
#include <string>

#include "io/image.h"

namespace fl::draw {

// The PNG file as bytes.
std::string encode_png(const io::Image8& image);

// encode_png, then written to a temporary file beside `path` that is renamed into place.
void write_png_atomic(const std::string& path, const io::Image8& image);

// Reads an opaque PNG (any alpha is dropped), for tests and tools. Throws InputError.
io::Image8 read_png(const std::string& path);

}  // namespace fl::draw
