#pragma once
// `plan SCENE.yaml`: for each material of a scene, the cheapest Fresnel model (derived, fitted or
// rendered parameters) whose error as rendered under the scene's lighting meets the scene's budget;
// the scene-wide choice among shader sets (one model, or one per group of materials: below); and
// the lookup tables (texture channels) they need.
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
// roughness kDefaultRoughness (roughness 0 is a mirror: analysis/lut/rendered.h). Relative file
// paths are taken relative to the scene file's folder when they exist there.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "analysis/lut/lut_accuracy.h"
#include "analysis/lut/lut_layout.h"
#include "analysis/speed/speed.h"
#include "analysis/study/study.h"

namespace fl::analysis {

constexpr double kDefaultMaxDe00 = 1.0;

struct SceneMaterial {
  std::string spec;               // as written, or resolved against the scene's folder
  int line = 0;                   // 1-based line in the scene file
  std::vector<double> roughness;  // the material's, else the scene's, else kDefaultRoughness
  std::string group;              // the scene's `group:` (empty: none)
  bool mirror() const;            // every roughness 0: the model at n·v, no table read
};
struct Scene {
  std::string path;
  std::vector<SceneMaterial> materials;
  double max_de00 = kDefaultMaxDe00;
  std::string space;  // empty: the run's working space
  int space_line = 0;
  bool punctual = false, ibl = false, area = false;
  std::vector<double> roughness;            // the scene's default
  std::vector<std::string> notes;           // the reader's merges (spectral::SceneFile::notes)
  std::vector<Lighting> lightings() const;  // punctual, ibl, area order
};

// Reads and checks a scene file (spectral::read_scene_file's InputErrors) and applies the defaults.
Scene read_scene(const std::string& path);

// Resolves and loads the scene's materials (a page glob gives every page it matches); a material
// that cannot be resolved is an InputError naming the scene file and the line of the material.
// A page glob's pages replace its entry in scene.materials (each with the entry's line and
// roughness), so that the materials and the scene's entries stay one to one; a page that two
// entries give is loaded once (roughness joined, a note added), and more than
// spectral::kMaxSceneMaterials pages in all is an InputError, before any is loaded.
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
  std::optional<int> texture_fetches;   // summed over the scene's lightings; nullopt: unmeasured
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

// The scene's shader sets: every way `plan` considers to shade the whole scene, what each costs the
// engine, its errors as rendered, its Pareto front and the choice.
//
// An option splits the scene's materials into groups (one group: a single shader; by class: metals
// and dielectrics; by the scene's own `group:` names) and gives each group one model; each material
// uses that model's parameter set (derived, fitted or rendered) of lowest error. A split is shaded
// as material permutations: each distinct model of the option is one shader variant, compiled
// apart, and a draw runs its own material's variant (no branch in the shader).
//
// Cost, compared lexicographically (scene_cost_less): per draw, the GPU instructions of the
// dearest variant (its functions for the scene's lightings summed, bench/gpu_costs.csv), then the
// texture fetches of the dearest variant, then the bytes of every table texture any variant
// reads (each texture once, lut_texture_bytes), then the number of variants. Per-pixel work comes
// first because it is paid for every pixel of every frame; table memory is paid once; a variant
// costs a compile and a state change per draw, so of two options otherwise equal the one with fewer
// shaders is cheaper. An unmeasured count (a model without a row in the cost file) is unknown and
// ranks after every measured one.
//
// Error: each material's error as rendered (the largest over the scene's lightings); an option's
// worst and median over the materials. Option A dominates B when A costs no more and errs no more
// at worst, and is cheaper or more accurate. The choice: if any option meets every material's
// budget, the cheapest of those (ties: the lower worst error, then the first listed); otherwise
// the lowest worst error (the largest excess over the budget), then the cheapest. Either way no
// option dominates the one chosen.

struct SceneCost {
  std::optional<int> gpu_instructions;  // the dearest variant per draw; nullopt: unmeasured
  std::optional<int> texture_fetches;   // the dearest variant per draw; nullopt: unmeasured
  long table_bytes = 0;                 // every texture read, once
  int variants = 1;                     // shader variants (distinct models)
};
// Lexicographic: instructions, texture fetches, table bytes, variants; unmeasured after measured.
bool scene_cost_less(const SceneCost& a, const SceneCost& b);

// The bytes of a table texture as an engine uploads it: size² texels × the components holding its
// table channels (lut_textures) × 2 (half floats) or 4 (floats).
long lut_texture_bytes(const std::string& texture, int size = kEngineLutSize,
                       TexelStorage storage = TexelStorage::Half);

// A partition of the scene's materials (indices into the scene's materials).
struct Grouping {
  std::string name;                         // "one shader", "by class", "by scene group"
  std::vector<std::string> names;           // each group's: "all", "metal", "dielectric", ...
  std::vector<std::vector<size_t>> groups;  // each non-empty
};
// One shader for all; metals and dielectrics when the scene has both; the scene's groups when it
// names at least one (materials without a group form "other") and they split it otherwise than the
// classes do.
std::vector<Grouping> scene_groupings(const std::vector<bool>& is_metal,
                                      const std::vector<std::string>& scene_group);

struct OptionGroup {
  std::string name;
  fresnel::Model model{};
  std::vector<size_t> materials;  // indices into the scene's materials
};
struct SceneOption {
  std::string name;  // the model, or "GROUP: model, GROUP: model"
  std::string grouping;
  std::vector<OptionGroup> groups;
  std::vector<PlanChoice> materials;  // in the scene's order: each its lowest-error set of its
                                      // group's model, meets_budget set
  SceneCost cost;
  double worst_de00 = 0, median_de00 = 0;
  std::vector<std::string> failing;    // materials over the budget
  std::optional<size_t> dominated_by;  // an option on the front that dominates this one
  bool meets_every_budget() const { return failing.empty(); }
};

// The options of every grouping: under "one shader" every model; under a split, every combination
// of the models each group keeps (a group drops a model that another matches or beats in
// instructions, fetches, textures needed — a subset — and worst error over the group, since
// swapping it in can only cheapen an option and lower its worst error), less those giving every
// group one model (the single-model option); when a grouping's combinations exceed 4096, the
// longest list drops its dearest model until they do not. candidates[k]: material k's
// (plan_candidates).
std::vector<SceneOption> scene_options(const Scene& scene,
                                       const std::vector<std::vector<PlanChoice>>& candidates,
                                       const std::vector<Grouping>& groupings, double max_de00);

// Sets dominated_by for every option (nullopt: on the Pareto front of cost against worst error).
void mark_dominated(std::vector<SceneOption>& options);
// The index of the option the plan recommends (see above).
size_t choose_scene_option(const std::vector<SceneOption>& options);

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

// The tables the chosen option reads, at the size and storage its budget allows.
struct PlanTables {
  int size = kEngineLutSize;  // texels per axis
  TexelStorage storage = TexelStorage::Float;
  long bytes = 0;         // every texture the option reads (lut_texture_bytes)
  double worst_de00 = 0;  // the option's worst error as rendered from these tables
  bool forced = false;    // the size was given (--lut-size), not chosen
};
// The sizes `plan` considers, each in half and float storage.
inline constexpr std::array<int, 4> kPlanLutSizes{16, 32, 64, 128};

struct Plan {
  Scene scene;
  std::string space;
  std::vector<PlanChoice> materials;
  std::vector<PlanLut> luts;               // for the per-material choices
  std::vector<SceneOption> scene_options;  // every option considered
  size_t chosen = 0;                       // the recommended one (choose_scene_option)
  std::vector<PlanLut> scene_luts;         // the tables the chosen option's shaders read
  PlanTables tables;                       // their size and storage
  const SceneOption& scene_choice() const { return scene_options.at(chosen); }
  std::vector<std::string> unmeasured;  // models without a CPU or GPU cost for the scene's lighting
};
// The tables material k of the chosen option reads (none for a mirror or under punctual lights).
std::vector<PlanLut> material_luts(const Plan& plan, size_t k);
// The options are weighed with the 64² float tables. The tables are then chosen for the chosen
// option: of every size in kPlanLutSizes (only `lut_size` when it is not 0; under area lights none
// below 64², since the LTC matrix's own accuracy is not part of the rendered error) in half and
// float, the fewest bytes with which every material's error as rendered stays within the larger
// of its budget and its error with the 64² float tables; at a forced size none may qualify, and
// the lower worst error is taken.
Plan make_plan(const Scene& scene, const Context& ctx, const std::vector<MaterialStudy>& studies,
               const PlanCosts& costs, int lut_size = 0);
// Sets plan.tables (see make_plan).
void choose_plan_tables(Plan& plan, const Context& ctx, const std::vector<MaterialStudy>& studies,
                        int lut_size);

}  // namespace fl::analysis
