#pragma once
// The harness of the optical-data readers: the input written to a temporary file, read, and
// sampled on the visible grid. Only fl::InputError may escape; a file the reader accepts must
// give a finite index with n > 0 and k ≥ 0 at every wavelength.
#include <cmath>

#include "fuzz_common.h"
#include "spectral/ri_database.h"
#include "util/errors.h"

namespace fl::fuzz {

template <class Read>
int fuzz_optical_reader(const std::string& path, const uint8_t* data, size_t size, Read read) {
  write_input(path, data, size);
  try {
    const auto oc = read(path);
    const auto s = spectral::sample_ior(oc, spectral::SpectralGrid::visible(5.0), "fuzz");
    for (const auto& v : s.ior.ior)
      require(std::isfinite(v.real()) && v.real() > 0.0 && std::isfinite(v.imag()) &&
              v.imag() >= 0.0);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace fl::fuzz
