#pragma once
// `plan SCENE.yaml`: for each material of a scene, the cheapest Fresnel model (derived or fitted
// parameters) whose RMS ΔE2000 against spectral ground truth meets the scene's budget, and the
// lookup tables the chosen models need under the scene's lighting.
//
// Scene file: spectral/scene_file.h. Defaults: max_de00 1.0, space --space, lighting punctual.
// Relative file paths are taken relative to the scene file's folder when they exist there.
#include <string>
#include <vector>

#include "analysis/tables/speed.h"
#include "analysis/study/study.h"

namespace fl::analysis {

constexpr double kDefaultMaxDe00 = 1.0;

struct SceneMaterial {
  std::string spec;  // as written, or resolved against the scene's folder
  int line = 0;      // 1-based line in the scene file
};
struct Scene {
  std::string path;
  std::vector<SceneMaterial> materials;
  double max_de00 = kDefaultMaxDe00;
  std::string space;  // empty: the run's working space
  int space_line = 0;
  bool punctual = false, ibl = false, area = false;
};

// Reads and checks a scene file (spectral::read_scene_file's InputErrors) and applies the defaults.
Scene read_scene(const std::string& path);

// Resolves and loads the scene's materials (a page glob gives every page it matches); a material
// that cannot be resolved is an InputError naming the scene file and the line of the material.
std::vector<LoadedMaterial> load_scene_materials(const Context& ctx, const Scene& scene);

struct PlanChoice {
  std::string material;  // display name
  fresnel::Model model{};
  bool fitted = false;
  std::vector<double> params;
  double rms_de00 = 0;
  double ns_per_eval = 0;
  bool meets_budget = false;  // false: no model meets it; this is the most accurate one
};

// The cheapest (model, parameter set) with RMS ΔE2000 ≤ max_de00; ties in cost go to the lower
// error. When none qualifies, the most accurate one, with meets_budget = false.
PlanChoice choose_model(const MaterialStudy& study, const ModelCosts& costs, double max_de00);

struct PlanLut {
  std::string name;      // dfg | ltc_matrix | ltc_moments | ltc_f82_moment
  std::string lighting;  // ibl | area
  std::vector<std::string> channels;
  std::string command;   // how to make it
};
// The tables the chosen models need under the scene's lighting, from each model's declaration
// (fresnel::PreIntegration): under IBL the split-sum DFG channels (plus the F82 channel for the F82
// model); under area lights the LTC matrix and n_D, plus f_D and l_D for the models whose Fresnel
// term they pre-integrate. Punctual lights need no table.
std::vector<PlanLut> needed_luts(const Scene& scene, const std::vector<PlanChoice>& choices);

struct Plan {
  Scene scene;
  std::string space;
  std::vector<PlanChoice> materials;
  std::vector<PlanLut> luts;
};
Plan make_plan(const Scene& scene, const Context& ctx, const std::vector<MaterialStudy>& studies,
               const ModelCosts& costs);

}  // namespace fl::analysis
