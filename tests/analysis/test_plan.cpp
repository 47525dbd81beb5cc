// `plan` (per material the cheapest model whose error as rendered under the scene's lighting meets
// the budget; one model for the whole scene; the lookup-table channels), `table speed`'s Pareto
// marks and the cost-file readers. The choices and the Pareto fronts are checked on hand-made
// (cost, error) tables whose answers are worked out below; the real-data plans against the models'
// declarations and the rendered errors computed independently of the plan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/plan/plan.h"
#include "analysis/speed/speed.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "test_util.h"
#include "util/errors.h"

namespace {

using fl::analysis::Lighting;
using fl::fresnel::Model;
using fl::fresnel::model_of;
namespace models = fl::fresnel::models;
using fl::test::TempDir;

fl::analysis::Settings settings() {
  fl::analysis::Settings s;
  s.paths.database = FL_DEFAULT_DB;
  s.paths.materials = FL_MATERIALS;
  return s;
}

fl::analysis::PlanCosts committed_costs() {
  return {fl::analysis::read_model_costs(FL_MODEL_COSTS),
          fl::analysis::read_gpu_costs(FL_GPU_COSTS)};
}

struct PlanRun {
  fl::analysis::Scene scene;
  fl::analysis::Plan plan;
};

PlanRun plan_for(const std::string& yaml) {
  TempDir dir;
  const std::string path = dir.file("scene.yaml", yaml);
  PlanRun r;
  r.scene = fl::analysis::read_scene(path);
  const fl::analysis::Context ctx(settings());
  const auto ms = fl::analysis::load_scene_materials(ctx, r.scene);
  const auto studies = fl::analysis::study_materials(ctx, ms, {});
  r.plan = fl::analysis::make_plan(r.scene, ctx, studies, committed_costs());
  return r;
}

std::vector<std::string> lut_names(const std::vector<fl::analysis::PlanLut>& luts) {
  std::vector<std::string> out;
  for (const auto& l : luts) out.push_back(l.name);
  return out;
}

// Every channel the model declares under each of the scene's pre-integrated lightings is listed.
void expect_served(const fl::analysis::Scene& scene, Model m,
                   const std::vector<fl::analysis::PlanLut>& luts) {
  for (Lighting l : scene.lightings()) {
    for (const char* ch : fl::analysis::lighting_support(m, l).channels) {
      bool listed = false;
      for (const auto& lut : luts)
        for (const auto& c : lut.channels)
          listed = listed || (lut.lighting == fl::analysis::lighting_name(l) &&
                              c.substr(c.find(' ') + 1) == ch);
      EXPECT_TRUE(listed) << fl::fresnel::model_spec(m).name << " needs " << ch << " under "
                          << fl::analysis::lighting_name(l);
    }
  }
}

TEST(Plan, FourDielectricsUnderPunctualLightsAtBudget2GetSchlick) {
  constexpr double kBudget = 2.0;
  const auto r = plan_for(
      "materials: [diamond, water, glass_bk7, acrylic]\nmax_de00: 2.0\nlighting: [punctual]\n");
  ASSERT_EQ(r.plan.materials.size(), 4u);
  for (const auto& m : r.plan.materials) {
    EXPECT_EQ(m.model, model_of<models::Schlick>) << m.material;
    EXPECT_TRUE(m.meets_budget) << m.material;
    EXPECT_EQ(m.error_lighting, Lighting::Punctual);
    EXPECT_LE(m.error, kBudget) << m.material;
    EXPECT_EQ(m.error, m.punctual_rms);  // the curve error, under punctual lights
  }
  EXPECT_TRUE(r.plan.luts.empty());                    // punctual lights need no table
  ASSERT_EQ(r.plan.scene_choice().groups.size(), 1u);  // four dielectrics: no class split
  EXPECT_EQ(r.plan.scene_choice().groups[0].model, model_of<models::Schlick>);
  EXPECT_EQ(r.plan.scene_choice().name, "schlick");
  EXPECT_TRUE(r.plan.scene_choice().failing.empty());
}

// Under IBL and area lights the budget is the rendered error: checked against the rendered errors
// of the same candidates, and every chosen model is served by the tables listed (or its
// approximation is the declared n·v one).
TEST(Plan, MetalsUnderIblAndAreaLightsBudgetTheRenderedError) {
  constexpr double kBudget = 0.5;
  const auto r = plan_for(
      "materials: [gold, copper, silver, aluminum, chromium]\nmax_de00: 0.5\nlighting: [ibl, "
      "area]\n");
  ASSERT_EQ(r.plan.materials.size(), 5u);
  const auto costs = committed_costs();
  for (const auto& m : r.plan.materials) {
    EXPECT_TRUE(m.meets_budget) << m.material;
    EXPECT_LE(std::max(m.ibl_rms, m.area_rms), kBudget) << m.material;
    EXPECT_EQ(m.error, std::max(m.ibl_rms, m.area_rms)) << m.material;
    const auto ibl = costs.gpu.of(m.model, Lighting::Ibl),
               area = costs.gpu.of(m.model, Lighting::Area);
    if (ibl && area)
      EXPECT_EQ(m.gpu_instructions, ibl->instructions + area->instructions) << m.material;
    else
      EXPECT_FALSE(m.gpu_instructions.has_value()) << m.material;
    expect_served(r.scene, m.model, r.plan.luts);
    for (Lighting l : {Lighting::Ibl, Lighting::Area}) {
      const auto& s = fl::analysis::lighting_support(m.model, l);
      EXPECT_TRUE(s.fresnel_pre_integrated || std::string(s.evaluated_at) == "n·v") << m.material;
    }
  }
  const auto& sc = r.plan.scene_choice();
  EXPECT_TRUE(sc.failing.empty());
  for (const auto& m : sc.materials) EXPECT_LE(m.error, kBudget) << m.material;
  for (const auto& g : sc.groups) expect_served(r.scene, g.model, r.plan.scene_luts);
  EXPECT_EQ(lut_names(r.plan.luts).front(), "dfg");
}

// The rendered error of a non-pre-integrable model (RGB η, κ at n·v) is far above its curve error
// on a rough dielectric seen at grazing angles: the budget under IBL rules it out where the curve
// would not.
TEST(Plan, NdotVApproximationIsMeasuredNotHidden) {
  const auto r =
      plan_for("materials:\n  - {name: glass_bk7, roughness: 0.8}\nmax_de00: 5\nlighting: ibl\n");
  const fl::analysis::Context ctx(settings());
  ASSERT_EQ(r.plan.materials.size(), 1u);
  EXPECT_EQ(r.plan.materials[0].roughness, std::vector<double>{0.8});
  EXPECT_NE(r.plan.materials[0].model, model_of<models::FresnelRgb>);
  auto scene = r.scene;
  const auto ms = fl::analysis::load_scene_materials(ctx, scene);
  const auto studies = fl::analysis::study_materials(ctx, ms, {});
  const auto points = fl::analysis::shading_points({0.8});
  const auto rendered = fl::analysis::rendered_candidates(ctx, studies[0], points);
  const auto rgb = std::find_if(rendered.begin(), rendered.end(), [](const auto& c) {
    return c.model == model_of<models::FresnelRgb> && c.set == fl::analysis::ParameterSet::Fitted;
  });
  ASSERT_NE(rgb, rendered.end());
  EXPECT_LT(rgb->punctual_rms, 0.05);  // the curve is the truth's
  EXPECT_GT(rgb->ibl.rms, 5.0);        // the lobe at grazing is not F(n·v) × lobe
}

// Every scene in examples/ under its lighting: each chosen model (per material and scene-wide) is
// served by the tables the plan lists, or shaded by its declared n·v approximation, whose
// rendered error is the one the plan reports (a finite number, compared with the budget).
TEST(Plan, ExampleScenesAreServedByTheirTablesOrNameTheirApproximation) {
  std::vector<std::string> scenes;
  for (const auto& e : std::filesystem::directory_iterator(FL_EXAMPLES_DIR))
    if (e.path().extension() == ".yaml") scenes.push_back(e.path().string());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 4u);
  bool lit[3] = {false, false, false};
  const fl::analysis::Context ctx(settings());
  for (const auto& path : scenes) {
    auto scene = fl::analysis::read_scene(path);
    const auto materials = fl::analysis::load_scene_materials(ctx, scene);
    const auto studies = fl::analysis::study_materials(ctx, materials, {});
    const auto plan = fl::analysis::make_plan(scene, ctx, studies, committed_costs());
    for (Lighting l : scene.lightings()) lit[static_cast<int>(l)] = true;
    std::vector<fl::analysis::PlanChoice> chosen = plan.materials;
    for (const auto& m : chosen) expect_served(scene, m.model, plan.luts);
    for (const auto& m : plan.scene_choice().materials)
      expect_served(scene, m.model, plan.scene_luts);
    chosen.insert(chosen.end(), plan.scene_choice().materials.begin(),
                  plan.scene_choice().materials.end());
    for (const auto& m : chosen) {
      for (Lighting l : scene.lightings()) {
        const auto& s = fl::analysis::lighting_support(m.model, l);
        if (l != Lighting::Punctual && !s.fresnel_pre_integrated) {
          EXPECT_EQ(std::string(s.evaluated_at), "n·v") << path;
        }
      }
      EXPECT_TRUE(std::isfinite(m.error)) << path << " " << m.material;
      EXPECT_EQ(m.meets_budget, m.error <= scene.max_de00) << path << " " << m.material;
    }
    std::printf("%s: scene-wide %s, %zu failing\n", path.c_str(), plan.scene_choice().name.c_str(),
                plan.scene_choice().failing.size());
  }
  EXPECT_TRUE(lit[0] && lit[1] && lit[2]) << "examples/ covers punctual, ibl and area";
}

// ---- Hand-made (cost, error) tables.
//
//   model                 gpu  cpu ns  error derived  error fitted
//   schlick                10    1       3.0           2.0
//   generalized_schlick    20    2       1.0           1.0
//   cook_torrance          30    3       1.0           0.5
//   lazanyi                20    2       2.5           1.2
//   f82                    20    2       0.9           0.9
//   gulbrandsen            40    4       0.5           0.5
//   fresnel_rgb            50    5       0.1           0.05
struct HandRow {
  Model model;
  int gpu;
  double ns, derived, fitted;
};
const std::vector<HandRow> kHand = {{model_of<models::Schlick>, 10, 1, 3.0, 2.0},
                                    {model_of<models::GeneralizedSchlick>, 20, 2, 1.0, 1.0},
                                    {model_of<models::CookTorrance>, 30, 3, 1.0, 0.5},
                                    {model_of<models::Lazanyi>, 20, 2, 2.5, 1.2},
                                    {model_of<models::F82>, 20, 2, 0.9, 0.9},
                                    {model_of<models::Gulbrandsen>, 40, 4, 0.5, 0.5},
                                    {model_of<models::FresnelRgb>, 50, 5, 0.1, 0.05}};

// A model of the registry without a row here (one added since) is unmeasured, with the largest
// error: it must change no choice and no front.
constexpr double kUnlistedError = 100.0;
const HandRow* hand_row(Model m) {
  const auto it =
      std::find_if(kHand.begin(), kHand.end(), [&](const HandRow& r) { return r.model == m; });
  return it == kHand.end() ? nullptr : &*it;
}
HandRow hand(Model m) {
  if (const auto* r = hand_row(m)) return *r;
  return {m, 0, 0, kUnlistedError, kUnlistedError};
}

fl::analysis::ModelCosts hand_costs() {
  fl::analysis::ModelCosts c;
  for (const auto& h : kHand) c.costs.push_back({h.model, h.ns});
  return c;
}
fl::analysis::GpuCosts hand_gpu() {
  fl::analysis::GpuCosts c;
  for (const auto& h : kHand)
    for (Lighting l : {Lighting::Punctual, Lighting::Ibl, Lighting::Area})
      c.costs.push_back({h.model, l, h.gpu, 1, 0, 0});
  return c;
}

// One material's candidates with the table's errors plus `offset`; `skip_fit` drops a fitted set.
std::vector<fl::analysis::PlanChoice> hand_candidates(const std::string& name, double offset = 0.0,
                                                      const Model* skip_fit = nullptr) {
  std::vector<fl::analysis::PlanChoice> out;
  for (const auto& spec : fl::fresnel::model_specs()) {
    for (int fitted = 0; fitted < 2; ++fitted) {
      if (fitted && skip_fit && *skip_fit == spec.model) continue;
      const auto h = hand(spec.model);
      fl::analysis::PlanChoice c;
      c.material = name;
      c.model = spec.model;
      c.set = fitted ? fl::analysis::ParameterSet::Fitted : fl::analysis::ParameterSet::Derived;
      c.params = {fitted ? 2.0 : 1.0};
      c.error = (fitted ? h.fitted : h.derived) + offset;
      if (hand_row(spec.model)) {
        c.gpu_instructions = h.gpu;
        c.texture_fetches = 0;
        c.ns_per_eval = h.ns;
      }
      out.push_back(c);
    }
  }
  return out;
}

fl::analysis::MaterialStudy hand_study(double offset = 0.0) {
  static const fl::analysis::LoadedMaterial material = [] {
    fl::analysis::LoadedMaterial m;
    m.material.name = "hand-made";
    return m;
  }();
  fl::analysis::MaterialStudy st;
  st.material = &material;
  for (const auto& spec : fl::fresnel::model_specs()) {
    fl::analysis::ModelResult r;
    r.model = spec.model;
    r.derived_error.rms = hand(spec.model).derived + offset;
    r.fitted_error.rms = hand(spec.model).fitted + offset;
    st.models.push_back(r);
  }
  return st;
}

TEST(Speed, ParetoFrontsOfAHandMadeTable) {
  const auto rows = fl::analysis::speed_rows({hand_study()}, hand_costs(), hand_gpu());
  ASSERT_EQ(rows.size(), 2 * fl::fresnel::model_specs().size());
  std::vector<std::string> front;
  for (const auto& r : rows) {
    EXPECT_EQ(r.pareto, r.pareto_gpu);  // the GPU costs here rank the models as the CPU costs do
    if (r.pareto)
      front.push_back(std::string(fl::fresnel::model_spec(r.model).name) +
                      (r.fitted ? " fitted" : " derived"));
  }
  // schlick fitted (cheapest); f82 both (a tie: neither dominates the other); cook_torrance fitted
  // (gulbrandsen is dearer and no better); fresnel_rgb fitted (derived: same cost, worse).
  std::vector<std::string> by_hand = {"schlick fitted", "cook_torrance fitted", "f82 derived",
                                      "f82 fitted", "fresnel_rgb fitted"};
  std::sort(front.begin(), front.end());
  std::sort(by_hand.begin(), by_hand.end());
  EXPECT_EQ(front, by_hand);
}

TEST(Speed, MedianAndMaxOverMaterials) {
  // Three materials: the table, the table + 7, and a perfect one (0): the median is the table's
  // value, the max the table + 7. With a fourth (table + 1) the median by nearest rank is the 2nd
  // of four (⌈0.5·4⌉), still the table's value (the mean of the middle two would be table + 0.5).
  fl::analysis::MaterialStudy perfect = hand_study();
  for (auto& r : perfect.models) r.derived_error.rms = r.fitted_error.rms = 0.0;
  const auto three =
      fl::analysis::speed_rows({hand_study(), hand_study(7.0), perfect}, hand_costs(), hand_gpu());
  const auto four = fl::analysis::speed_rows(
      {hand_study(), hand_study(7.0), perfect, hand_study(1.0)}, hand_costs(), hand_gpu());
  for (size_t k = 0; k < three.size(); ++k) {
    const auto h = hand(three[k].model);
    const double e = three[k].fitted ? h.fitted : h.derived;
    EXPECT_DOUBLE_EQ(three[k].median_rms_de00, e);
    EXPECT_DOUBLE_EQ(three[k].max_rms_de00, e + 7.0);
    if (hand_row(three[k].model)) {
      EXPECT_DOUBLE_EQ(three[k].ns_per_eval.value(), h.ns);
      EXPECT_EQ(three[k].gpu.value().instructions, h.gpu);
    } else {
      EXPECT_FALSE(three[k].ns_per_eval || three[k].gpu);  // unmeasured
    }
    EXPECT_DOUBLE_EQ(four[k].median_rms_de00, e);
  }
}

TEST(Plan, ChoiceOnAHandMadeTable) {
  const auto cands = hand_candidates("hand-made");
  struct Want {
    double budget;
    Model model;
    bool fitted;
    double error;
    bool meets;
  };
  for (const Want& w : std::vector<Want>{
           {2.5, model_of<models::Schlick>, true, 2.0,
            true},  // the cheapest model, fitted, fits the budget
           {2.0, model_of<models::Schlick>, true, 2.0, true},  // the budget is inclusive
           {1.0, model_of<models::F82>, false, 0.9,
            true},  // three at 20 qualify; the lowest error wins; derived first on a tie
           {0.5, model_of<models::CookTorrance>, true, 0.5,
            true},  // not gulbrandsen (as good, dearer)
           {0.07, model_of<models::FresnelRgb>, true, 0.05, true},
           {0.01, model_of<models::FresnelRgb>, true, 0.05,
            false}}) {  // nothing qualifies: the most accurate
    const auto c = fl::analysis::choose_model(cands, w.budget);
    EXPECT_EQ(c.model, w.model) << "budget " << w.budget;
    EXPECT_EQ(c.set == fl::analysis::ParameterSet::Fitted, w.fitted) << "budget " << w.budget;
    EXPECT_EQ(c.error, w.error) << "budget " << w.budget;
    EXPECT_EQ(c.meets_budget, w.meets) << "budget " << w.budget;
    EXPECT_EQ(c.params, std::vector<double>{w.fitted ? 2.0 : 1.0}) << "budget " << w.budget;
  }
  // Without cook_torrance's fitted set, at 0.5 the next is gulbrandsen's derived set.
  const Model ct = model_of<models::CookTorrance>;
  const auto c = fl::analysis::choose_model(hand_candidates("hand-made", 0.0, &ct), 0.5);
  EXPECT_EQ(c.model, model_of<models::Gulbrandsen>);
  EXPECT_EQ(c.set, fl::analysis::ParameterSet::Derived);
}

// A candidate whose cost is unmeasured ranks after every measured one: chosen only when no
// measured candidate meets the budget.
TEST(Plan, UnmeasuredCostRanksLast) {
  auto cands = hand_candidates("hand-made");
  auto unmeasure = [&](Model m) {
    for (auto& c : cands)
      if (c.model == m) c.gpu_instructions.reset(), c.ns_per_eval.reset();
  };
  unmeasure(model_of<models::Schlick>);
  auto c = fl::analysis::choose_model(cands, 2.5);  // schlick fitted (2.0) is no longer first
  EXPECT_EQ(c.model, model_of<models::F82>);
  EXPECT_EQ(c.set, fl::analysis::ParameterSet::Derived);
  unmeasure(model_of<models::FresnelRgb>);
  c = fl::analysis::choose_model(cands, 0.07);  // only fresnel_rgb fitted (0.05) qualifies
  EXPECT_EQ(c.model, model_of<models::FresnelRgb>);
  EXPECT_TRUE(c.meets_budget);
  EXPECT_FALSE(c.gpu_instructions.has_value());
}

// Punctual lights read no table: the hand-made options cost their instructions alone.
fl::analysis::Scene punctual_scene() {
  fl::analysis::Scene s;
  s.punctual = true;
  return s;
}

std::vector<fl::analysis::SceneOption> single_options(
    const std::vector<std::vector<fl::analysis::PlanChoice>>& cands, double budget) {
  const size_t n = cands.size();
  std::vector<bool> metal(n, true);
  auto options = fl::analysis::scene_options(
      punctual_scene(), cands, fl::analysis::scene_groupings(metal, std::vector<std::string>(n)),
      budget);
  fl::analysis::mark_dominated(options);
  return options;
}

const fl::analysis::SceneOption& named(const std::vector<fl::analysis::SceneOption>& options,
                                       const std::string& name) {
  const auto it =
      std::find_if(options.begin(), options.end(), [&](const auto& o) { return o.name == name; });
  if (it == options.end()) throw std::runtime_error("no option " + name);
  return *it;
}

// Three materials: the table, the table + 0.3, the table + 0.6; one model for all, each material
// with its lower-error set. Worst errors: schlick 2.6, generalized_schlick 1.6, cook_torrance 1.1,
// lazanyi 1.8, f82 1.5, gulbrandsen 1.1, fresnel_rgb 0.65. At budget 1.5 f82 (20 instructions) is
// the cheapest meeting every budget; at 1.0 only fresnel_rgb does; at 0.3 none does, and
// fresnel_rgb has the smallest worst error (B and C fail).
TEST(Plan, SceneWideChoiceOnAHandMadeTable) {
  const std::vector<std::vector<fl::analysis::PlanChoice>> cands{
      hand_candidates("A"), hand_candidates("B", 0.3), hand_candidates("C", 0.6)};
  auto options = single_options(cands, 1.5);
  ASSERT_EQ(options.size(), fl::fresnel::model_specs().size());
  auto s = options[fl::analysis::choose_scene_option(options)];
  EXPECT_EQ(s.name, "f82");
  EXPECT_TRUE(s.failing.empty());
  EXPECT_NEAR(s.worst_de00, 1.5, 1e-12);
  EXPECT_NEAR(s.median_de00, 1.2, 1e-12);
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.materials[0].set, fl::analysis::ParameterSet::Derived);  // 0.9 either way
  options = single_options(cands, 1.0);
  s = options[fl::analysis::choose_scene_option(options)];
  EXPECT_EQ(s.name, "fresnel_rgb");
  EXPECT_TRUE(s.failing.empty());
  EXPECT_EQ(s.materials[0].set, fl::analysis::ParameterSet::Fitted);
  options = single_options(cands, 0.3);
  s = options[fl::analysis::choose_scene_option(options)];
  EXPECT_EQ(s.name, "fresnel_rgb");
  EXPECT_EQ(s.failing, (std::vector<std::string>{"B", "C"}));
  EXPECT_EQ(s.cost.gpu_instructions, 50);
  // The front of cost against worst error: schlick (10, 2.6), f82 (20, 1.5), cook_torrance
  // (30, 1.1), fresnel_rgb (50, 0.65). generalized_schlick and lazanyi (20) lose to f82;
  // gulbrandsen (40, 1.1) to cook_torrance; an unmeasured model to schlick.
  for (const auto& o : options) {
    const bool front = o.name == "schlick" || o.name == "f82" || o.name == "cook_torrance" ||
                       o.name == "fresnel_rgb";
    EXPECT_EQ(!o.dominated_by, front) << o.name;
  }
  auto by = [&](const std::string& name) {
    return options[*named(options, name).dominated_by].name;
  };
  EXPECT_EQ(by("generalized_schlick"), "f82");
  EXPECT_EQ(by("lazanyi"), "f82");
  EXPECT_EQ(by("gulbrandsen"), "cook_torrance");
  for (const auto& spec : fl::fresnel::model_specs())
    if (!hand_row(spec.model)) {
      EXPECT_EQ(by(spec.name), "schlick");
    }
}

// Two materials, a metal M and a dielectric D, with errors chosen per model (every other model
// 5.0; instructions from the hand-made table, no table read):
//   M: schlick 0.4, f82 0.3            D: schlick 1.5, f82 2.0, cook_torrance 0.8, fresnel_rgb 0.2
// The metal group keeps schlick and f82 (every other model loses to schlick), the dielectric group
// schlick, cook_torrance and fresnel_rgb, so the class split gives 2 × 3 − 1 = 5 options beside
// the 10 single models. At budget 1.0 no single model passes (schlick's worst is 1.5); the splits
// "schlick | cook_torrance" and "f82 | cook_torrance" pass at 30 instructions, 2 variants; the
// first listed is chosen. "f82 | fresnel_rgb" (50, 0.3) beats "schlick | fresnel_rgb" (50, 0.4).
TEST(Plan, ClassSplitOnAHandMadeTable) {
  auto make = [](const std::string& name, std::vector<std::pair<Model, double>> errors) {
    auto c = hand_candidates(name);
    for (auto& x : c) {
      x.error = 5.0;
      for (const auto& [m, e] : errors)
        if (x.model == m) x.error = e;
    }
    return c;
  };
  const Model schlick = model_of<models::Schlick>, f82 = model_of<models::F82>,
              ct = model_of<models::CookTorrance>, rgb = model_of<models::FresnelRgb>;
  const std::vector<std::vector<fl::analysis::PlanChoice>> cands{
      make("M", {{schlick, 0.4}, {f82, 0.3}}),
      make("D", {{schlick, 1.5}, {f82, 2.0}, {ct, 0.8}, {rgb, 0.2}})};
  const auto groupings = fl::analysis::scene_groupings({true, false}, {"", ""});
  ASSERT_EQ(groupings.size(), 2u);
  auto options = fl::analysis::scene_options(punctual_scene(), cands, groupings, 1.0);
  fl::analysis::mark_dominated(options);
  ASSERT_EQ(options.size(), fl::fresnel::model_specs().size() + 5);
  const auto& chosen = options[fl::analysis::choose_scene_option(options)];
  EXPECT_EQ(chosen.name, "metal: schlick, dielectric: cook_torrance");
  EXPECT_EQ(chosen.cost.gpu_instructions, 30);
  EXPECT_EQ(chosen.cost.variants, 2);
  EXPECT_NEAR(chosen.worst_de00, 0.8, 1e-12);
  // The median of {0.4, 0.8} by nearest rank: the 1st of two (⌈0.5·2⌉ = 1).
  EXPECT_NEAR(chosen.median_de00, 0.4, 1e-12);
  using V = std::vector<std::string>;
  V front;
  for (const auto& o : options)
    if (!o.dominated_by) front.push_back(o.name);
  EXPECT_EQ(front,
            (V{"schlick", "metal: schlick, dielectric: cook_torrance",
               "metal: f82, dielectric: cook_torrance", "metal: f82, dielectric: fresnel_rgb"}));
  EXPECT_EQ(options[*named(options, "metal: schlick, dielectric: fresnel_rgb").dominated_by].name,
            "metal: f82, dielectric: fresnel_rgb");
  EXPECT_EQ(options[*named(options, "metal: f82, dielectric: schlick").dominated_by].name,
            "schlick");
  EXPECT_EQ(options[*named(options, "cook_torrance").dominated_by].name, "schlick");
}

// The cost tuple is compared in order; a split's extra variant breaks a tie; unmeasured is last.
TEST(Plan, SceneCostOrder) {
  using fl::analysis::SceneCost;
  EXPECT_TRUE(fl::analysis::scene_cost_less({19, 2, 81920, 1}, {27, 4, 131072, 1}));
  EXPECT_TRUE(fl::analysis::scene_cost_less({19, 4, 0, 1}, {27, 2, 0, 1}));
  EXPECT_TRUE(fl::analysis::scene_cost_less({19, 2, 81920, 1}, {19, 2, 81920, 2}));
  EXPECT_TRUE(fl::analysis::scene_cost_less({19, 2, 0, 2}, {19, 2, 81920, 1}));
  EXPECT_TRUE(fl::analysis::scene_cost_less({500, 2, 0, 1}, {std::nullopt, 2, 0, 1}));
  EXPECT_FALSE(fl::analysis::scene_cost_less({19, 2, 0, 1}, {19, 2, 0, 1}));
  // 64² texels × components × 2 bytes: dfg RGB, ltc_1 RGBA.
  EXPECT_EQ(fl::analysis::lut_texture_bytes("dfg"), 64 * 64 * 3 * 2);
  EXPECT_EQ(fl::analysis::lut_texture_bytes("ltc_1"), 64 * 64 * 4 * 2);
}

TEST(Plan, Groupings) {
  using V = std::vector<std::string>;
  auto g = fl::analysis::scene_groupings({true, true, false}, {"", "", ""});
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[1].names, (V{"metal", "dielectric"}));
  EXPECT_EQ(g[1].groups, (std::vector<std::vector<size_t>>{{0, 1}, {2}}));
  g = fl::analysis::scene_groupings({true, true, true}, {"trim", "", "trim"});
  ASSERT_EQ(g.size(), 2u);  // no class split among metals only; the scene's groups
  EXPECT_EQ(g[1].names, (V{"trim", "other"}));
  EXPECT_EQ(g[1].groups, (std::vector<std::vector<size_t>>{{0, 2}, {1}}));
  g = fl::analysis::scene_groupings({true, false}, {"a", "b"});  // the class partition again
  EXPECT_EQ(g.size(), 2u);
}

// Roughness 0 is a mirror: the truth is the spectral curve at n·v, and every model renders as
// itself at n·v under either lighting, so the rendered ΔE2000 at each view angle is the ΔE2000
// between the ground truth and the model evaluated at cos(view), computed here directly.
TEST(Plan, RoughnessZeroRendersTheCurveAtNdotV) {
  const fl::analysis::Context ctx(settings());
  TempDir dir;
  auto scene = fl::analysis::read_scene(
      dir.file("m.yaml", "materials:\n  - {name: copper, roughness: 0}\nlighting: [ibl, area]\n"));
  EXPECT_TRUE(scene.materials[0].mirror());
  const auto ms = fl::analysis::load_scene_materials(ctx, scene);
  const auto points = fl::analysis::shading_points({0.0});
  ASSERT_EQ(points.size(), fl::analysis::kShadingViewDeg.size());
  const auto truth = fl::analysis::lobe_truth(ctx, ms[0], points);
  const auto studies = fl::analysis::study_materials(ctx, ms, {});
  for (const auto& spec : fl::fresnel::model_specs()) {
    const auto& params = studies[0].result(spec.model).derived;
    for (Lighting l : {Lighting::Ibl, Lighting::Area}) {
      const auto de = fl::analysis::rendered_de00(ctx, truth, spec.model, params, l, points);
      for (size_t k = 0; k < points.size(); ++k) {
        const double mu = std::cos(fl::analysis::kShadingViewDeg[k] * std::numbers::pi / 180.0);
        const auto exact =
            fl::analysis::ground_truth_rgb(ctx, ms[0].ior, mu, ctx.settings().eta_outside);
        const auto model = spec.evaluate(mu, params.data(), false);
        const double want = fl::color::ciede2000(ctx.rgb_to_lab(exact), ctx.rgb_to_lab(model));
        EXPECT_NEAR(de[k], want, 2e-3) << spec.name << " at " << fl::analysis::kShadingViewDeg[k];
      }
    }
  }
}

// A scene of mirrors and fully rough materials: the plan reads no table for the mirror and says so.
TEST(Plan, MirrorsAndFullyRoughMaterialsArePlanned) {
  const auto r = plan_for(
      "materials:\n  - {name: silver, roughness: 0}\n  - {name: glass_bk7, roughness: [0, 1]}\n"
      "  - {name: gold, roughness: 1}\nmax_de00: 1.0\nlighting: [ibl, area]\n");
  ASSERT_EQ(r.plan.materials.size(), 3u);
  EXPECT_TRUE(fl::analysis::material_luts(r.plan, 0).empty());   // silver: a mirror
  EXPECT_FALSE(fl::analysis::material_luts(r.plan, 1).empty());  // glass at roughness 1 too
  for (const auto& m : r.plan.scene_choice().materials) EXPECT_TRUE(std::isfinite(m.error));
}

TEST(Plan, LookupTableChannelsPerLighting) {
  auto channels = [](const fl::analysis::Scene& s, std::vector<Model> models) {
    std::vector<std::string> out;
    for (const auto& l : fl::analysis::needed_luts(s, models))
      for (const auto& c : l.channels) out.push_back(l.name + ":" + c);
    return out;
  };
  fl::analysis::Scene punctual, ibl, area, all;
  punctual.punctual = true;
  ibl.ibl = true;
  area.area = true;
  all.punctual = all.ibl = all.area = true;
  using V = std::vector<std::string>;
  const Model f82 = model_of<models::F82>, schlick = model_of<models::Schlick>,
              gul = model_of<models::Gulbrandsen>;
  EXPECT_EQ(channels(punctual, {f82}), V{});
  EXPECT_EQ(channels(ibl, {f82, schlick}), (V{"dfg:R dfg1", "dfg:G dfg2", "dfg:B dfg_f82"}));
  EXPECT_EQ(channels(ibl, {schlick}), (V{"dfg:R dfg1", "dfg:G dfg2"}));
  EXPECT_EQ(channels(ibl, {gul}), (V{"dfg:R dfg1", "dfg:G dfg2"}));  // F(n·v) × (dfg1 + dfg2)
  EXPECT_EQ(channels(area, {gul}), (V{"ltc_1:RGBA ltc_matrix", "ltc_2:R n_d"}));
  EXPECT_EQ(channels(area, {schlick, gul}),
            (V{"ltc_1:RGBA ltc_matrix", "ltc_2:R n_d", "ltc_2:G f_d"}));
  EXPECT_EQ(channels(all, {f82}),
            (V{"dfg:R dfg1", "dfg:G dfg2", "dfg:B dfg_f82", "ltc_1:RGBA ltc_matrix", "ltc_2:R n_d",
               "ltc_2:G f_d", "ltc_2:B l_d"}));
}

TEST(Plan, UnservableMaterialIsReportedWithItsBestModel) {
  const auto r = plan_for("materials: [chromium]\nmax_de00: 0.001\n");
  ASSERT_EQ(r.plan.materials.size(), 1u);
  EXPECT_FALSE(r.plan.materials[0].meets_budget);
  EXPECT_GT(r.plan.materials[0].error, 0.001);
  EXPECT_EQ(r.plan.scene_choice().failing, std::vector<std::string>{"Chromium"});
}

TEST(Plan, SceneDefaultsAndRoughness) {
  TempDir dir;
  auto s = fl::analysis::read_scene(dir.file("s.yaml", "materials: [gold]\n"));
  EXPECT_EQ(s.max_de00, fl::analysis::kDefaultMaxDe00);
  EXPECT_TRUE(s.punctual);
  EXPECT_FALSE(s.ibl || s.area);
  EXPECT_TRUE(s.space.empty());
  const std::vector<double> defaults(fl::analysis::kDefaultRoughness.begin(),
                                     fl::analysis::kDefaultRoughness.end());
  EXPECT_EQ(s.materials[0].roughness, defaults);
  s = fl::analysis::read_scene(
      dir.file("r.yaml",
               "roughness: [0.3, 0.7]\nmaterials:\n  - gold\n  - {name: copper, roughness: 0.25}\n "
               " - name: silver\n    roughness: [0.1, 1]\n"));
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.materials[0].roughness, (std::vector<double>{0.3, 0.7}));
  EXPECT_EQ(s.materials[1].roughness, (std::vector<double>{0.25}));
  EXPECT_EQ(s.materials[1].spec, "copper");
  EXPECT_EQ(s.materials[2].roughness, (std::vector<double>{0.1, 1.0}));
  // Roughness 0 (a mirror) and groups.
  s = fl::analysis::read_scene(
      dir.file("g.yaml",
               "materials:\n  - {name: gold, roughness: 0, group: trim}\n  - {name: water, "
               "roughness: [0, 1]}\n"));
  EXPECT_EQ(s.materials[0].roughness, (std::vector<double>{0.0}));
  EXPECT_EQ(s.materials[0].group, "trim");
  EXPECT_TRUE(s.materials[0].mirror());
  EXPECT_TRUE(s.materials[1].group.empty());
  EXPECT_FALSE(s.materials[1].mirror());
}

TEST(Plan, SceneErrorsNameFileAndLine) {
  TempDir dir;
  auto message = [&](const std::string& yaml) -> std::string {
    const std::string p = dir.file("bad.yaml", yaml);
    try {
      fl::analysis::read_scene(p);
    } catch (const fl::InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(message("materials: [gold]\nlighting: [area, sun]\n")
                .find("bad.yaml:2: unknown lighting 'sun'"),
            std::string::npos);
  EXPECT_NE(message("materials: [gold]\nmax_de00: lots\n")
                .find("bad.yaml:2: 'max_de00' must be a positive number"),
            std::string::npos);
  EXPECT_NE(message("materials: [gold]\nmax_de00: -1\n").find("bad.yaml:2:"), std::string::npos);
  EXPECT_NE(message("materials: [gold\n").find("bad.yaml:"), std::string::npos);
  EXPECT_NE(message("max_de00: 1\n").find("missing 'materials'"), std::string::npos);
  EXPECT_NE(message("materials: []\n").find("bad.yaml:1:"), std::string::npos);
  EXPECT_NE(message("materials: [gold]\nlights: [area]\n").find("bad.yaml:2: unknown key 'lights'"),
            std::string::npos);
  EXPECT_NE(message("materials: [gold]\nroughness: 1.5\n")
                .find("bad.yaml:2: 'roughness' must be a perceptual roughness in [0, 1]"),
            std::string::npos);
  EXPECT_NE(
      message("materials:\n  - {name: gold, roughness: -0.1}\n").find("bad.yaml:2: 'roughness'"),
      std::string::npos);
  EXPECT_NE(message("materials:\n  - {name: gold, group: [a, b]}\n")
                .find("bad.yaml:2: a material's 'group' must be a string"),
            std::string::npos);
  EXPECT_NE(message("materials:\n  - {name: gold, group: ''}\n").find("bad.yaml:2: empty group"),
            std::string::npos);
  EXPECT_NE(message("materials:\n  - {name: gold, shine: 1}\n")
                .find("bad.yaml:2: unknown material key 'shine'"),
            std::string::npos);
}

TEST(Plan, UnknownMaterialNamesSceneLine) {
  TempDir dir;
  const std::string p =
      dir.file("scene.yaml", "max_de00: 1\nmaterials:\n  - gold\n  - unobtainium\n");
  auto scene = fl::analysis::read_scene(p);
  const fl::analysis::Context ctx(settings());
  try {
    fl::analysis::load_scene_materials(ctx, scene);
    FAIL() << "expected InputError";
  } catch (const fl::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(p + ":4: unknown material 'unobtainium'", 0), 0u)
        << e.what();
  }
}

TEST(Speed, CostsFileErrors) {
  TempDir dir;
  auto message = [&](auto read, const std::string& text) -> std::string {
    try {
      read(dir.file("costs.csv", text));
    } catch (const fl::InputError& e) {
      return e.what();
    }
    return "no error";
  };
  const auto cpu = [](const std::string& p) { fl::analysis::read_model_costs(p); };
  EXPECT_NE(message(cpu, "model,ns\n").find("costs.csv:1: header"), std::string::npos);
  EXPECT_NE(message(cpu, "model,ns_per_eval_float_batched\nschlick,abc\n")
                .find("costs.csv:2: cost 'abc'"),
            std::string::npos);
  // A model without a row is unmeasured, not an error.
  const auto only_schlick = fl::analysis::read_model_costs(
      dir.file("costs.csv", "model,ns_per_eval_float_batched\nschlick,1\n"));
  EXPECT_EQ(only_schlick.ns_per_eval(model_of<models::Schlick>), 1.0);
  EXPECT_FALSE(only_schlick.ns_per_eval(model_of<models::F82>).has_value());
  EXPECT_NE(message(cpu, "model,ns_per_eval_float_batched\nwarp,1\n")
                .find("costs.csv:2: unknown model 'warp'"),
            std::string::npos);
  const auto gpu = [](const std::string& p) { fl::analysis::read_gpu_costs(p); };
  const std::string header = "model,lighting,instructions,arithmetic,extended,texture\n";
  EXPECT_NE(message(gpu, "model,lighting\n").find("costs.csv:1: header"), std::string::npos);
  EXPECT_NE(
      message(gpu, header + "schlick,sun,1,1,0,0\n").find("costs.csv:2: unknown lighting 'sun'"),
      std::string::npos);
  EXPECT_NE(message(gpu, header + "schlick,ibl,1.5,1,0,0\n").find("costs.csv:2: count '1.5'"),
            std::string::npos);
  EXPECT_NE(message(gpu, header + "schlick,ibl,1,1,0,0\nschlick,ibl,1,1,0,0\n")
                .find("costs.csv:3: 'schlick' under ibl listed twice"),
            std::string::npos);
  const auto only_ibl =
      fl::analysis::read_gpu_costs(dir.file("costs.csv", header + "schlick,ibl,1,1,0,0\n"));
  EXPECT_EQ(only_ibl.of(model_of<models::Schlick>, Lighting::Ibl).value().instructions, 1);
  EXPECT_FALSE(only_ibl.of(model_of<models::Schlick>, Lighting::Punctual).has_value());
}

}  // namespace
