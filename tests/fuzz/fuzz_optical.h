#pragma once
// The harness of the optical-data readers: the input written to a temporary file, read, and
// sampled on the visible grid. Only fl::InputError may escape; a file the reader accepts must
// give, at every wavelength, what its rows and formulas are held to (tabulated.h, value_problem):
// n in (0, kMaxOpticalConstant] and k in [0, kMaxOpticalConstant].
#include <complex>

#include "fuzz_common.h"
#include "spectral/ri_database.h"
#include "spectral/tabulated.h"
#include "util/errors.h"

namespace fl::fuzz {

inline bool physical(const std::complex<double>& ior) {
  return ior.real() > 0.0 && ior.real() <= spectral::kMaxOpticalConstant && ior.imag() >= 0.0 &&
         ior.imag() <= spectral::kMaxOpticalConstant;
}

template <class Read>
int fuzz_optical_reader(const std::string& path, const uint8_t* data, size_t size, Read read) {
  write_input(path, data, size);
  try {
    const auto oc = read(path);
    const auto s = spectral::sample_ior(oc, spectral::SpectralGrid::visible(5.0), "fuzz");
    for (const auto& v : s.ior.ior) require(physical(v));
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace fl::fuzz
