// `plan` (the cheapest model within a ΔE2000 budget per scene material, and the lookup tables it
// needs), `table speed`'s Pareto marks and the model-costs file reader. The choice and the Pareto
// front are checked on hand-made (cost, error) tables whose answers are worked out below.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "analysis/plan/plan.h"
#include "analysis/tables/speed.h"
#include "spectral/errors.h"
#include "test_util.h"

namespace {

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
  fl::analysis::StudyOptions o;
  const auto studies = fl::analysis::study_materials(ctx, ms, o);
  r.plan = fl::analysis::make_plan(r.scene, ctx, studies, fl::analysis::read_model_costs(FL_MODEL_COSTS));
  return r;
}

bool has_lut(const fl::analysis::Plan& p, const std::string& name) {
  return std::any_of(p.luts.begin(), p.luts.end(), [&](const auto& l) { return l.name == name; });
}

TEST(Plan, FourDielectricsAtBudget2GetSchlick) {
  constexpr double kBudget = 2.0;
  const auto r = plan_for("materials: [diamond, water, glass_bk7, acrylic]\nmax_de00: 2.0\nlighting: [punctual]\n");
  ASSERT_EQ(r.plan.materials.size(), 4u);
  for (const auto& m : r.plan.materials) {
    EXPECT_EQ(m.model, model_of<models::Schlick>) << m.material;
    EXPECT_TRUE(m.meets_budget) << m.material;
    EXPECT_LE(m.rms_de00, kBudget) << m.material;
  }
  EXPECT_TRUE(r.plan.luts.empty());  // punctual lights need no table
}

TEST(Plan, MetalsAtBudgetHalfUnderAreaLightsGetLtcTablesAndMeetTheBudget) {
  constexpr double kBudget = 0.5;
  const auto r = plan_for("materials: [gold, copper, silver, aluminum, chromium]\nmax_de00: 0.5\nlighting: [area]\n");
  ASSERT_EQ(r.plan.materials.size(), 5u);
  const auto costs = fl::analysis::read_model_costs(FL_MODEL_COSTS);
  bool f82 = false;
  for (const auto& m : r.plan.materials) {
    EXPECT_TRUE(m.meets_budget) << m.material;
    EXPECT_LE(m.rms_de00, kBudget) << m.material;
    EXPECT_EQ(m.ns_per_eval, costs.ns_per_eval(m.model)) << m.material;
    f82 = f82 || m.model == model_of<models::F82>;
  }
  EXPECT_TRUE(has_lut(r.plan, "ltc_matrix"));
  EXPECT_TRUE(has_lut(r.plan, "ltc_moments"));
  EXPECT_EQ(has_lut(r.plan, "ltc_f82_moment"), f82);  // the F82 moment only with an F82 model
  EXPECT_FALSE(has_lut(r.plan, "dfg"));
}

// ---- Hand-made (cost, error) tables.
//
//   model                 ns   derived  fitted     front (by hand)
//   schlick                1    3.0      2.0        fitted
//   generalized_schlick    2    1.0      1.0        -      (f82 is as cheap and better)
//   cook_torrance          3    1.0      0.5        fitted
//   lazanyi                2    2.5      1.2        -
//   f82                    2    0.9      0.9        both   (a tie: neither dominates the other)
//   gulbrandsen            4    0.5      0.5        -      (cook_torrance fitted: cheaper, as good)
//   fresnel_rgb            5    0.1      0.05       fitted (derived: same cost, worse)
struct HandRow {
  Model model;
  double ns, derived, fitted;
};
const std::vector<HandRow> kHand = {
    {model_of<models::Schlick>, 1, 3.0, 2.0}, {model_of<models::GeneralizedSchlick>, 2, 1.0, 1.0}, {model_of<models::CookTorrance>, 3, 1.0, 0.5},
    {model_of<models::Lazanyi>, 2, 2.5, 1.2}, {model_of<models::F82>, 2, 0.9, 0.9},              {model_of<models::Gulbrandsen>, 4, 0.5, 0.5},
    {model_of<models::FresnelRgb>, 5, 0.1, 0.05}};

fl::analysis::ModelCosts hand_costs() {
  fl::analysis::ModelCosts c;
  for (const auto& spec : fl::fresnel::model_specs())
    for (const auto& h : kHand)
      if (h.model == spec.model) c.costs.push_back({h.model, h.ns});
  return c;
}

// One study whose RMS errors are the table's plus `offset`; `unusable` marks one model's fit failed.
fl::analysis::MaterialStudy hand_study(double offset = 0.0, Model unusable_fit = model_of<models::Schlick>, bool any_unusable = false) {
  static const fl::analysis::LoadedMaterial material = [] {
    fl::analysis::LoadedMaterial m;
    m.material.name = "hand-made";
    return m;
  }();
  fl::analysis::MaterialStudy st;
  st.material = &material;
  for (const auto& spec : fl::fresnel::model_specs()) {
    const auto h = std::find_if(kHand.begin(), kHand.end(), [&](const HandRow& r) { return r.model == spec.model; });
    EXPECT_NE(h, kHand.end()) << spec.name << " is missing from the hand-made table";
    if (h == kHand.end()) continue;
    fl::analysis::ModelResult r;
    r.model = h->model;
    r.derived = {1.0};
    r.derived_error.rms = h->derived + offset;
    r.fitted.parameters = {2.0};
    r.fitted.usable = !(any_unusable && h->model == unusable_fit);
    r.fitted_error.rms = h->fitted + offset;
    st.models.push_back(r);
  }
  return st;
}

TEST(Speed, ParetoFrontOfAHandMadeTable) {
  const auto rows = fl::analysis::speed_rows({hand_study()}, hand_costs());
  ASSERT_EQ(rows.size(), 2 * kHand.size());
  std::vector<std::string> front;
  for (const auto& r : rows)
    if (r.pareto) front.push_back(std::string(fl::fresnel::model_spec(r.model).name) + (r.fitted ? " fitted" : " derived"));
  const std::vector<std::string> by_hand = {"schlick fitted", "cook_torrance fitted", "f82 derived", "f82 fitted",
                                            "fresnel_rgb fitted"};
  std::vector<std::string> sorted_front = front, sorted_hand = by_hand;
  std::sort(sorted_front.begin(), sorted_front.end());
  std::sort(sorted_hand.begin(), sorted_hand.end());
  EXPECT_EQ(sorted_front, sorted_hand);
}

TEST(Speed, MedianAndMaxOverMaterials) {
  // Three materials: the table, the table + 7, and a perfect one (0): the median is the table's
  // value, the max the table + 7. With a fourth material (table + 1) the median of an even count
  // is the mean of the middle two: table + 0.5.
  fl::analysis::MaterialStudy perfect = hand_study();
  for (auto& r : perfect.models) r.derived_error.rms = r.fitted_error.rms = 0.0;
  const auto three = fl::analysis::speed_rows({hand_study(), hand_study(7.0), perfect}, hand_costs());
  const auto four = fl::analysis::speed_rows({hand_study(), hand_study(7.0), perfect, hand_study(1.0)}, hand_costs());
  for (size_t k = 0; k < three.size(); ++k) {
    const auto h = std::find_if(kHand.begin(), kHand.end(), [&](const HandRow& r) { return r.model == three[k].model; });
    ASSERT_NE(h, kHand.end());
    const double e = three[k].fitted ? h->fitted : h->derived;
    EXPECT_DOUBLE_EQ(three[k].median_rms_de00, e);
    EXPECT_DOUBLE_EQ(three[k].max_rms_de00, e + 7.0);
    EXPECT_DOUBLE_EQ(three[k].ns_per_eval, h->ns);
    EXPECT_DOUBLE_EQ(four[k].median_rms_de00, e + 0.5);
  }
}

TEST(Plan, ChoiceOnAHandMadeTable) {
  const auto study = hand_study();
  const auto costs = hand_costs();
  struct Want {
    double budget;
    Model model;
    bool fitted;
    double rms;
    bool meets;
  };
  for (const Want& w : std::vector<Want>{
           {2.5, model_of<models::Schlick>, true, 2.0, true},       // the cheapest model, fitted, fits the budget
           {2.0, model_of<models::Schlick>, true, 2.0, true},       // the budget is inclusive
           {1.0, model_of<models::F82>, false, 0.9, true},          // three at 2 ns qualify; the lowest error wins; derived first on a tie
           {0.5, model_of<models::CookTorrance>, true, 0.5, true},  // not gulbrandsen (as good, dearer)
           {0.07, model_of<models::FresnelRgb>, true, 0.05, true},
           {0.01, model_of<models::FresnelRgb>, true, 0.05, false}}) {  // nothing qualifies: the most accurate
    const auto c = fl::analysis::choose_model(study, costs, w.budget);
    EXPECT_EQ(c.model, w.model) << "budget " << w.budget;
    EXPECT_EQ(c.fitted, w.fitted) << "budget " << w.budget;
    EXPECT_EQ(c.rms_de00, w.rms) << "budget " << w.budget;
    EXPECT_EQ(c.meets_budget, w.meets) << "budget " << w.budget;
    EXPECT_EQ(c.params, std::vector<double>{w.fitted ? 2.0 : 1.0}) << "budget " << w.budget;
  }
  // A fit that failed is not a candidate: at 0.5 the next is gulbrandsen's derived set.
  const auto c = fl::analysis::choose_model(hand_study(0.0, model_of<models::CookTorrance>, true), costs, 0.5);
  EXPECT_EQ(c.model, model_of<models::Gulbrandsen>);
  EXPECT_FALSE(c.fitted);
}

TEST(Plan, LookupTablesPerLighting) {
  auto names = [](const fl::analysis::Scene& s, std::vector<Model> models) {
    std::vector<fl::analysis::PlanChoice> choices;
    for (Model m : models) {
      fl::analysis::PlanChoice c;
      c.model = m;
      choices.push_back(c);
    }
    std::vector<std::string> out;
    for (const auto& l : fl::analysis::needed_luts(s, choices)) out.push_back(l.name);
    return out;
  };
  fl::analysis::Scene punctual, ibl, area, all;
  punctual.punctual = true;
  ibl.ibl = true;
  area.area = true;
  all.punctual = all.ibl = all.area = true;
  using V = std::vector<std::string>;
  EXPECT_EQ(names(punctual, {model_of<models::F82>}), V{});
  EXPECT_EQ(names(ibl, {model_of<models::F82>, model_of<models::Schlick>}), (V{"dfg", "dfg_f82"}));
  EXPECT_EQ(names(ibl, {model_of<models::Schlick>}), V{"dfg"});
  EXPECT_EQ(names(area, {model_of<models::Schlick>, model_of<models::Gulbrandsen>}), (V{"ltc_matrix", "ltc_moments"}));
  EXPECT_EQ(names(area, {model_of<models::Schlick>, model_of<models::F82>}), (V{"ltc_matrix", "ltc_moments", "ltc_f82_moment"}));
  EXPECT_EQ(names(all, {model_of<models::F82>}),
            (V{"dfg", "dfg_f82", "ltc_matrix", "ltc_moments", "ltc_f82_moment"}));
}

TEST(Plan, UnservableMaterialIsReportedWithItsBestModel) {
  const auto r = plan_for("materials: [chromium]\nmax_de00: 0.001\n");
  ASSERT_EQ(r.plan.materials.size(), 1u);
  EXPECT_FALSE(r.plan.materials[0].meets_budget);
  EXPECT_GT(r.plan.materials[0].rms_de00, 0.001);
}

TEST(Plan, IblNeedsDfgOnly) {
  const auto r = plan_for("materials: [gold]\nlighting: ibl\n");
  ASSERT_EQ(r.plan.luts.size(), 1u);
  EXPECT_EQ(r.plan.luts[0].name, "dfg");
}

TEST(Plan, SceneDefaults) {
  TempDir dir;
  const auto s = fl::analysis::read_scene(dir.file("s.yaml", "materials: [gold]\n"));
  EXPECT_EQ(s.max_de00, fl::analysis::kDefaultMaxDe00);
  EXPECT_TRUE(s.punctual);
  EXPECT_FALSE(s.ibl || s.area);
  EXPECT_TRUE(s.space.empty());
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
  EXPECT_NE(message("materials: [gold]\nlighting: [area, sun]\n").find("bad.yaml:2: unknown lighting 'sun'"), std::string::npos);
  EXPECT_NE(message("materials: [gold]\nmax_de00: lots\n").find("bad.yaml:2: 'max_de00' must be a positive number"), std::string::npos);
  EXPECT_NE(message("materials: [gold]\nmax_de00: -1\n").find("bad.yaml:2:"), std::string::npos);
  EXPECT_NE(message("materials: [gold\n").find("bad.yaml:"), std::string::npos);
  EXPECT_NE(message("max_de00: 1\n").find("missing 'materials'"), std::string::npos);
  EXPECT_NE(message("materials: []\n").find("bad.yaml:1:"), std::string::npos);
  EXPECT_NE(message("materials: [gold]\nlights: [area]\n").find("bad.yaml:2: unknown key 'lights'"), std::string::npos);
}

TEST(Plan, UnknownMaterialNamesSceneLine) {
  TempDir dir;
  const std::string p = dir.file("scene.yaml", "max_de00: 1\nmaterials:\n  - gold\n  - unobtainium\n");
  const auto scene = fl::analysis::read_scene(p);
  const fl::analysis::Context ctx(settings());
  try {
    fl::analysis::load_scene_materials(ctx, scene);
    FAIL() << "expected InputError";
  } catch (const fl::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(p + ":4: unknown material 'unobtainium'", 0), 0u) << e.what();
  }
}

TEST(Speed, CostsFileErrors) {
  TempDir dir;
  auto message = [&](const std::string& text) -> std::string {
    try {
      fl::analysis::read_model_costs(dir.file("costs.csv", text));
    } catch (const fl::InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(message("model,ns\n").find("costs.csv:1: header"), std::string::npos);
  EXPECT_NE(message("model,ns_per_eval_float_batched\nschlick,abc\n").find("costs.csv:2: cost 'abc'"), std::string::npos);
  EXPECT_NE(message("model,ns_per_eval_float_batched\nschlick,1\n").find("no cost for model"), std::string::npos);
  EXPECT_NE(message("model,ns_per_eval_float_batched\nwarp,1\n").find("costs.csv:2: unknown model 'warp'"), std::string::npos);
}

}  // namespace
