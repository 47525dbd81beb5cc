// libFuzzer target: spectral CGATS reader (read_cgats_spectra + resample, as cie.cpp uses it).
#include <cmath>

#include "fuzz_common.h"
#include "spectral/cie.h"
#include "spectral/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path(".cmf");
  fl::fuzz::write_input(path, data, size);
  try {
    const auto c = fl::spectral::read_cgats_spectra(path);
    fl::fuzz::require(!c.sets.empty() && c.lambda_nm.size() >= 2);
    for (const auto& set : c.sets) {
      fl::fuzz::require(set.size() == c.lambda_nm.size());
      const auto s =
          fl::spectral::resample(c.lambda_nm, set, fl::spectral::SpectralGrid::visible(5.0));
      for (double v : s.values) fl::fuzz::require(std::isfinite(v));
    }
  } catch (const fl::InputError&) {
  }
  return 0;
}
