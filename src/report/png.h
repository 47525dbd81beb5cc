#pragma once
// PNG files through libpng (libpng stays inside png.cpp). Output is byte-identical for the same
// pixels: no time chunk, no text chunks, fixed zlib level and row filter.
#include <string>

#include "report/image.h"

namespace fl::report {

// The PNG file (8-bit RGB, non-interlaced) as bytes.
std::string encode_png(const Image8& image);

// encode_png, then written to a temporary file beside `path` that is renamed into place.
void write_png_atomic(const std::string& path, const Image8& image);

// Reads an 8-bit RGB or RGBA PNG (alpha dropped), for tests and tools. Throws InputError.
Image8 read_png(const std::string& path);

}  // namespace fl::report
