#pragma once
// Scene files for `plan`, read as written (the defaults are analysis/plan.h's). A YAML map:
//   materials: [gold, main/Cu/nk/Johnson, my_glass.yml]   # catalog names, database pages, page
//   globs
//                                                        # or files, or {name: gold, roughness: 0.3
//                                                        | [0.2, 0.5], group: jewellery}
//   max_de00: 1.0                                        # optional RMS ΔE2000 budget
//   space: acescg                                        # optional working space
//   lighting: [punctual, ibl, area]                      # optional, any of these (or one of them)
//   roughness: [0.2, 0.6]                                # optional, every material's default
// Roughness is perceptual (α = roughness²), in [0, 1]; 0 is a mirror. A material's `group: NAME`
// names a group of materials `plan` may give a shader of its own.
#include <optional>
#include <string>
#include <vector>

namespace fl::spectral {

struct SceneFileMaterial {
  std::string spec;               // as written
  int line = 0;                   // 1-based line in the scene file
  std::vector<double> roughness;  // empty: not given
  std::string group;              // empty: not given
};

struct SceneFile {
  std::string path;
  std::vector<SceneFileMaterial> materials;  // at least one
  std::optional<double> max_de00;            // positive when given
  std::string space;                         // empty: not given
  int space_line = 0;
  bool punctual = false, ibl = false, area = false;  // the lighting listed
  std::vector<double> roughness;                     // empty: not given
};

// InputError naming the file and line for a missing file, a directory, an empty file, invalid
// YAML, an unknown key, an empty or non-string material list, an unknown lighting, a budget
// that is not a positive number, a roughness outside [0, 1], or a group that is not a
// non-empty string.
SceneFile read_scene_file(const std::string& path);

}  // namespace fl::spectral
