// libFuzzer target: J.A. Woollam WVASE .mat reader (read_wvase_mat + sample_ior), through the
// extension dispatch the CLI uses.
#include <cmath>

#include "fuzz_common.h"
#include "spectral/nk_text.h"
#include "spectral/ri_database.h"
#include "util/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path(".mat");
  fl::fuzz::write_input(path, data, size);
  try {
    const auto oc = fl::spectral::read_optical_file(path);
    const auto s = fl::spectral::sample_ior(oc, fl::spectral::SpectralGrid::visible(5.0), "fuzz");
    for (const auto& v : s.ior.ior)
      fl::fuzz::require(std::isfinite(v.real()) && v.real() > 0.0 && std::isfinite(v.imag()) &&
                        v.imag() >= 0.0);
  } catch (const fl::InputError&) {
  }
  return 0;
}
