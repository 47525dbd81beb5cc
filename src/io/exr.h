#pragma once
// Float EXR images for lookup tables (OpenEXR stays inside exr.cpp).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fl::io {

// A scanline image of 32-bit float channels. Pixel (x, y) of channel c is
// pixels[(y·width + x)·channels.size() + c]; row y = 0 is the first row of the file.
struct ExrImage {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // e.g. R, G, B, A
  std::vector<float> pixels;
  std::vector<std::pair<std::string, std::string>> string_attributes;
  std::vector<std::pair<std::string, float>> float_attributes;
  // The standard chromaticities attribute: red x, y, green x, y, blue x, y, white x, y (absent:
  // OpenEXR's default, Rec.709 primaries with a D65 white).
  std::optional<std::array<float, 8>> chromaticities;
  bool half = false;  // stored as half floats (the pixels rounded to nearest even), else float
};

// The EXR file (ZIP-compressed float or half channels, the attributes in the header) as bytes, for
// write_files_atomic.
std::string encode_exr(const ExrImage& image);

// encode_exr, then written with write_file_atomic (io/writer.h).
void write_exr_atomic(const std::string& path, const ExrImage& image);

// The IEEE 754 binary16 bit pattern nearest to `v` (round to nearest even; OpenEXR's half), for
// half-float tables such as Filament's RGB16F DFG texture.
std::uint16_t half_bits(float v);

// Reads every channel of an EXR file as float pixels (any pixel type, scanline or tiled), with the
// string and float attributes and the chromaticities. Throws InputError naming the file for what
// spectral::check_input_file refuses, a data window that is empty or holds more than 2^28 values,
// and whatever OpenEXR cannot read.
ExrImage read_exr(const std::string& path);

}  // namespace fl::io
