#pragma once
// `plan SCENE.yaml`: for each material of a scene, the cheapest Fresnel model (derived, fitted or
// rendered parameters) whose error as rendered under the scene's lighting meets the scene's budget;
// the scene-wide choice (one shader: the cheapest single model meeting every material's budget);
// and the lookup tables (texture channels) they need.
//
// Error as rendered (analysis/lut/rendered.h): under `ibl` and `area` the RMS ΔE2000 over the
// material's roughness values × the shading view angles, of what the engine computes from the
// tables (or the model at n·v where no table pre-integrates it) against brute-force spectral
// integration of the GGX lobe; under `punctual` the curve's RMS ΔE2000. With several lightings
// the budget applies to the largest of their errors, and the plan names which lighting that was.
// Cost: the GPU instruction count of the model's shader functions for the scene's lightings
// (bench/gpu_costs.csv), then CPU ns per evaluation (bench/model_costs.csv), then the error. A
// model without a row in a cost file is unmeasured: its cost is unknown, so it ranks after every
// measured cost, and the plan names it.
//
// Scene file: spectral/scene_file.h. Defaults: max_de00 1.0, space --space, lighting punctual,
// roughness kDefaultRoughness. Relative file paths are taken relative to the scene file's folder
// when they exist there.
#include <optional>
#include <string>
#include <vector>

#include "analysis/lut/lut_layout.h"
#include "analysis/study/study.h"
#include "analysis/tables/lut_accuracy.h"
#include "analysis/tables/speed.h"

namespace fl::analysis {

constexpr double kDefaultMaxDe00 = 1.0;

struct SceneMaterial {
  std::string spec;               // as written, or resolved against the scene's folder
  int line = 0;                   // 1-based line in the scene file
  std::vector<double> roughness;  // the material's, else the scene's, else kDefaultRoughness
};
struct Scene {
  std::string path;
  std::vector<SceneMaterial> materials;
  double max_de00 = kDefaultMaxDe00;
  std::string space;  // empty: the run's working space
  int space_line = 0;
  bool punctual = false, ibl = false, area = false;
  std::vector<double> roughness;            // the scene's default
  std::vector<Lighting> lightings() const;  // punctual, ibl, area order
};

// Reads and checks a scene file (spectral::read_scene_file's InputErrors) and applies the defaults.
Scene read_scene(const std::string& path);

// Resolves and loads the scene's materials (a page glob gives every page it matches); a material
// that cannot be resolved is an InputError naming the scene file and the line of the material.
// A page glob's pages replace its entry in scene.materials (each with the entry's line and
// roughness), so that the materials and the scene's entries stay one to one.
std::vector<LoadedMaterial> load_scene_materials(const Context& ctx, Scene& scene);

// The costs a plan weighs.
struct PlanCosts {
  ModelCosts cpu;
  GpuCosts gpu;
};

// One (model, parameter set) for one material, with its errors and cost under the scene's lighting.
struct PlanChoice {
  std::string material;  // display name
  fresnel::Model model{};
  ParameterSet set = ParameterSet::Derived;
  std::vector<double> params;
  std::vector<double> roughness;
  double punctual_rms = 0, ibl_rms = 0, area_rms = 0;  // the scene's lightings only
  double error = 0;                                    // the budgeted one: the largest
  Lighting error_lighting = Lighting::Punctual;        // whose error that is
  std::optional<int> gpu_instructions;  // summed over the scene's lightings; nullopt: unmeasured
  std::optional<double> ns_per_eval;    // nullopt: unmeasured
  bool meets_budget =
      false;           // per material: false means no model meets it; this is the most accurate
  color::Rgb f_avg{};  // hemispherical average 2∫F μ dμ (fresnel/average.h)
};

// Every candidate of one material under the scene's lighting.
std::vector<PlanChoice> plan_candidates(const Scene& scene,
                                        const std::vector<RenderedCandidate>& rendered,
                                        const std::string& material,
                                        const std::vector<double>& roughness,
                                        const PlanCosts& costs);
// The cheapest candidate with error ≤ max_de00 (ties: CPU ns, then error; an unmeasured cost
// after every measured one); when none qualifies, the most accurate, with meets_budget = false.
PlanChoice choose_model(const std::vector<PlanChoice>& candidates, double max_de00);

// One shader for the scene: one model for every material, each material with its parameter set
// (derived, fitted or rendered) of lowest error.
struct SceneChoice {
  fresnel::Model model{};
  std::vector<PlanChoice> materials;    // meets_budget per material
  std::vector<std::string> failing;     // materials over the budget
  std::optional<int> gpu_instructions;  // nullopt: unmeasured
  std::optional<double> ns_per_eval;
  double max_error = 0;
};
// The cheapest model meeting every budget (ties: CPU ns, then the largest error); if none does, the
// one failing fewest materials (ties: the largest error, then cost).
SceneChoice choose_scene_model(const std::vector<std::vector<PlanChoice>>& candidates,
                               double max_de00);

struct PlanLut {
  std::string name;      // dfg | ltc_1 | ltc_2 (analysis/lut/lut_layout.h)
  std::string lighting;  // ibl | area
  std::string file;
  std::vector<std::string> channels;  // "R dfg1", ... (the texture components holding each)
  std::string command;                // how to make it
};
// The texture channels the models need under the scene's lighting, from each model's declaration
// (fresnel::PreIntegration). Punctual lights need no table.
std::vector<PlanLut> needed_luts(const Scene& scene, const std::vector<fresnel::Model>& models);

struct Plan {
  Scene scene;
  std::string space;
  std::vector<PlanChoice> materials;
  std::vector<PlanLut> luts;  // for the per-material choices
  SceneChoice scene_choice;
  std::vector<PlanLut> scene_luts;      // for the scene-wide model
  std::vector<std::string> unmeasured;  // models without a CPU or GPU cost for the scene's lighting
};
Plan make_plan(const Scene& scene, const Context& ctx, const std::vector<MaterialStudy>& studies,
               const PlanCosts& costs);

}  // namespace fl::analysis
