// Issue 6: `plan` (the cheapest model within a ΔE2000 budget per scene material, and the lookup
// tables it needs), `table speed`'s Pareto marks and the model-costs file reader.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "analysis/plan.h"
#include "analysis/speed.h"
#include "spectral/errors.h"
#include "test_util.h"

namespace {

using fl::fresnel::Model;
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
    EXPECT_EQ(m.model, Model::Schlick) << m.material;
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
    f82 = f82 || m.model == Model::F82;
  }
  EXPECT_TRUE(has_lut(r.plan, "ltc_matrix"));
  EXPECT_TRUE(has_lut(r.plan, "ltc_moments"));
  EXPECT_EQ(has_lut(r.plan, "ltc_f82_moment"), f82);  // the F82 moment only with an F82 model
  EXPECT_FALSE(has_lut(r.plan, "dfg"));
}

TEST(Plan, ChosenModelIsTheCheapestWithinBudget) {
  // Exhaustively: no cheaper (model, parameter set) meets the budget.
  const fl::analysis::Context ctx(settings());
  const auto costs = fl::analysis::read_model_costs(FL_MODEL_COSTS);
  std::vector<fl::analysis::LoadedMaterial> ms;
  for (const char* key : {"iron", "gold", "ruby"})
    ms.push_back(fl::analysis::load_material(ctx, fl::spectral::resolve_material(key, ctx.settings().paths)));
  fl::analysis::StudyOptions o;
  const auto studies = fl::analysis::study_materials(ctx, ms, o);
  for (double budget : {0.05, 0.3, 1.0, 3.0}) {
    for (const auto& st : studies) {
      const auto c = fl::analysis::choose_model(st, costs, budget);
      double best = 1e300;
      for (const auto& r : st.models) {
        const double ns = costs.ns_per_eval(r.model);
        for (double e : {r.derived_error.rms, r.fitted_error.rms}) {
          best = std::min(best, e);
          if (e <= budget) EXPECT_GE(ns, c.ns_per_eval) << st.material->material.name << " budget " << budget;
        }
      }
      if (c.meets_budget) EXPECT_LE(c.rms_de00, budget);
      else EXPECT_EQ(c.rms_de00, best) << "an unserved material reports its most accurate model";
    }
  }
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

TEST(Speed, ParetoRowsAreNotDominated) {
  const fl::analysis::Context ctx(settings());
  std::vector<fl::analysis::LoadedMaterial> ms;
  for (const char* key : {"gold", "water"})
    ms.push_back(fl::analysis::load_material(ctx, fl::spectral::resolve_material(key, ctx.settings().paths)));
  fl::analysis::StudyOptions o;
  const auto rows = fl::analysis::speed_rows(fl::analysis::study_materials(ctx, ms, o),
                                             fl::analysis::read_model_costs(FL_MODEL_COSTS));
  constexpr size_t kRowsPerModel = 2;  // derived, fitted
  ASSERT_EQ(rows.size(), kRowsPerModel * fl::fresnel::model_specs().size());
  int front = 0;
  for (const auto& a : rows) {
    bool dominated = false;
    for (const auto& b : rows)
      dominated = dominated || (b.ns_per_eval <= a.ns_per_eval && b.median_rms_de00 <= a.median_rms_de00 &&
                                (b.ns_per_eval < a.ns_per_eval || b.median_rms_de00 < a.median_rms_de00));
    EXPECT_EQ(a.pareto, !dominated);
    front += a.pareto;
  }
  EXPECT_GE(front, 1);
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
