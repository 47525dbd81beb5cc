// libFuzzer target: refractiveindex.info YAML reader (read_refractiveindex_file + sample_ior).
#include "fuzz_optical.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path(".yml");
  return fl::fuzz::fuzz_optical_reader(path, data, size, [](const std::string& p) {
    return fl::spectral::read_refractiveindex_file(p);
  });
}
