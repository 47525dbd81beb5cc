#pragma once
// A lookup-table texture as a C header that compiles as C99 and as C++: its texels, exactly as the
// EXR file of the same texture holds them, in one static array named from a symbol, so headers of
// different tables (different symbols) share a translation unit.
//
//   #ifndef SYMBOL_H                      (the symbol in upper case)
//   #define SYMBOL_SIZE N                 texels per axis (the textures are square)
//   #define SYMBOL_CHANNELS C
//   static const float SYMBOL_data[SYMBOL_SIZE * SYMBOL_SIZE * SYMBOL_CHANNELS] = {...};
//
// Texel (x, y), channel c is SYMBOL_data[(y * SYMBOL_SIZE + x) * SYMBOL_CHANNELS + c]; the comment
// above repeats the texture's attributes (axes, channels, the shader code that reads it).
#include <string>
#include <vector>

#include "io/exr.h"

namespace fl::documents {

struct CHeader {
  std::string symbol;        // a C identifier (check_c_symbol)
  std::string generated_by;  // the command that wrote it, for the first comment line
  bool half = false;  // uint16_t half-float bit patterns (an RGB16F texture) instead of float
};
std::string c_header(const io::ExrImage& texture, const CHeader& header);

// The body of a C array initializer: `texels_per_line` texels of `channels` values per line, as
// floats (%.9e) or, with `half`, as half-float bit patterns (0x3c00).
std::string c_array_values(const std::vector<float>& values, size_t channels,
                           size_t texels_per_line, bool half);

// InputError unless `symbol` is a C identifier of at most 64 characters.
void check_c_symbol(const std::string& symbol);

}  // namespace fl::documents
