// libFuzzer target: material catalog entry reader (read_catalog_entry + sample_ior). A small
// synthetic database page main/Good/nk/Synthetic holds a valid file so that `source:` can resolve.
// An accepted entry has a source, an order within ±1000000, a finite talk error and physical
// optical constants (fuzz_optical.h).
#include <cmath>
#include <filesystem>

#include "fuzz_optical.h"
#include "spectral/material.h"
#include "util/errors.h"

namespace {

fl::spectral::DataPaths make_paths() {
  namespace fs = std::filesystem;
  const std::string root = fl::fuzz::temp_path("_db");
  fs::create_directories(root + "/data/main/Good/nk");
  const char yml[] =
      "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 0.1\n        0.9 1.6 0.2\n";
  fl::fuzz::write_input(root + "/data/main/Good/nk/Synthetic.yml",
                        reinterpret_cast<const uint8_t*>(yml), sizeof(yml) - 1);
  return {root, root};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fl::spectral::DataPaths paths = make_paths();
  static const std::string path = fl::fuzz::temp_path("_entry.yml");
  fl::fuzz::write_input(path, data, size);
  try {
    const auto m = fl::spectral::read_catalog_entry(path, paths);
    fl::fuzz::require(!m.source.empty() && std::abs(m.order) <= 1000000 &&
                      std::isfinite(m.talk_schlick_rms_de00));
    const auto s =
        fl::spectral::sample_ior(m.constants, fl::spectral::SpectralGrid::visible(5.0), m.name);
    for (const auto& v : s.ior.ior) fl::fuzz::require(fl::fuzz::physical(v));
  } catch (const fl::InputError&) {
  }
  return 0;
}
