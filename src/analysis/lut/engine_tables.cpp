// How an engine stores and reads its tables: texel storage and the tables `lut` writes
// (analysis/lut/rendered.h).
#include <algorithm>
#include <cmath>

#include "analysis/lut/rendered.h"

namespace fl::analysis {

namespace {

// Half-float rounding of a float: 11 significant bits, ties to even; below 2⁻¹⁴ the subnormal
// spacing 2⁻²⁴.
double round_to_half(float f) {
  const double v = f;
  if (v == 0.0 || !std::isfinite(v)) return v;
  int e = 0;
  std::frexp(v, &e);  // |v| in [2^(e − 1), 2^e)
  const double spacing = std::ldexp(1.0, std::max(e, -13) - 11);
  return std::nearbyint(v / spacing) * spacing;
}

}  // namespace

const char* texel_storage_name(TexelStorage s) {
  switch (s) {
    case TexelStorage::Float:
      return "float";
    case TexelStorage::Half:
      return "half";
    case TexelStorage::Unorm16:
      return "unorm16";
  }
  return "?";
}

double stored_texel(TexelStorage s, double v) {
  switch (s) {
    case TexelStorage::Float:
      return static_cast<float>(v);
    case TexelStorage::Half:
      return round_to_half(static_cast<float>(v));
    case TexelStorage::Unorm16:
      return std::nearbyint(std::clamp(v, 0.0, 1.0) * 65535.0) / 65535.0;
  }
  return v;
}

EngineTables engine_tables(int size, TexelStorage storage) {
  return {dfg_grid(size), ltc_grid(size), storage};
}

}  // namespace fl::analysis
