#pragma once
// The pixels of a Cairo image surface (RGB24, or ARGB32 with its alpha dropped) as an image: the
// rasterizer (drawing.cpp) and the PNG reader (png.cpp) share it.
#include <cairo.h>

#include "io/image.h"

namespace fl::draw {

io::Image8 surface_pixels(cairo_surface_t* s);

}  // namespace fl::draw
