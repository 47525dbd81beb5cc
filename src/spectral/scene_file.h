#pragma once
// Scene files for `plan`, read as written (the defaults are analysis/plan/plan.h's). A YAML map:
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

// A scene's limits, which keep `plan` within seconds (docs/engines.md): distinct materials (after
// merging repeated entries and expanding page globs) and distinct roughness values per list.
constexpr int kMaxSceneMaterials = 64;
constexpr int kMaxSceneRoughnessValues = 8;

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
  std::vector<std::string> notes;  // what was merged ("'gold' listed 3 times (lines 2, 3, 4): ...")
};

// InputError naming the file and line for a missing file, a directory, an empty file, invalid
// YAML, an unknown key, an empty or non-string material list, an unknown lighting, a budget
// that is not a positive number, a roughness outside [0, 1], or a group that is not a
// non-empty string; more than kMaxSceneMaterials distinct materials or kMaxSceneRoughnessValues
// distinct roughness values in a list. A material named again (the same text) is merged into its
// first entry (roughness lists joined; its groups must agree) and a repeated roughness value
// dropped, each merge with a note.
SceneFile read_scene_file(const std::string& path);

}  // namespace fl::spectral
