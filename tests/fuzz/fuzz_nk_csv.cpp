// libFuzzer target: table reader (read_nk_table + sample_ior).
#include "fuzz_optical.h"
#include "spectral/nk_text.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path(".csv");
  return fl::fuzz::fuzz_optical_reader(
      path, data, size, [](const std::string& p) { return fl::spectral::read_nk_table(p); });
}
