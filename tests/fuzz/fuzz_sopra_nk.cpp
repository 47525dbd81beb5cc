// libFuzzer target: SOPRA .nk reader (read_sopra_nk + sample_ior), through the extension dispatch
// the CLI uses.
#include "fuzz_optical.h"
#include "spectral/nk_text.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path(".nk");
  return fl::fuzz::fuzz_optical_reader(
      path, data, size, [](const std::string& p) { return fl::spectral::read_optical_file(p); });
}
