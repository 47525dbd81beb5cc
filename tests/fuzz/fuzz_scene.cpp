// libFuzzer target: scene file reader (read_scene_file, as `plan` uses it). An accepted scene
// must hold what scene_file.h promises: at least one material, each with a name and a line;
// roughness in [0, 1] (0 is a mirror); a positive, finite budget; a non-empty space with its line.
#include <cmath>

#include "fuzz_common.h"
#include "spectral/scene_file.h"
#include "util/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = fl::fuzz::temp_path("_scene.yaml");
  fl::fuzz::write_input(path, data, size);
  try {
    const auto s = fl::spectral::read_scene_file(path);
    fl::fuzz::require(!s.materials.empty());
    for (const auto& m : s.materials) {
      fl::fuzz::require(!m.spec.empty() && m.line >= 1);
      for (double r : m.roughness) fl::fuzz::require(r >= 0.0 && r <= 1.0);
    }
    for (double r : s.roughness) fl::fuzz::require(r >= 0.0 && r <= 1.0);
    if (s.max_de00) fl::fuzz::require(std::isfinite(*s.max_de00) && *s.max_de00 > 0.0);
    if (!s.space.empty()) fl::fuzz::require(s.space_line >= 1);
  } catch (const fl::InputError&) {
  }
  return 0;
}
