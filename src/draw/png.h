#pragma once
// PNG files: 8-bit RGB rows encoded by libpng, every row unfiltered and compressed at zlib's
// default level, with no time or text chunks, so the same pixels give the same bytes. (libpng's
// default, each row's filter chosen adaptively, which Cairo's PNG writer keeps, takes twice the
// time for files about 4 % smaller.) Drawings are rasterized by Cairo (drawing.h) and encoded here.
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
