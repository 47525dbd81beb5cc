// `plan SCENE.yaml`: the cheapest Fresnel model per scene material within a ΔE2000 budget, and the
// lookup tables the chosen models need under the scene's lighting.
#include <fmt/format.h>

#include <memory>

#include "analysis/plan/plan.h"
#include "cli/app.h"
#include "report/plan_report.h"
#include "spectral/errors.h"

namespace fl::cli {

void add_plan_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "plan", "per scene material the cheapest Fresnel model within a ΔE2000 budget, and the lookup tables it needs");
  struct Args {
    std::string scene, format = "md", costs;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("SCENE", a->scene,
                  "scene YAML: materials (list), max_de00 (default 1.0), space, lighting (punctual, ibl, area)")
      ->required();
  sub->add_option("--format", a->format, "json or md")->capture_default_str();
  sub->add_option("--costs", a->costs, "model costs file (default $FRESNEL_LAB_COSTS or the committed bench/model_costs.csv)");
  sub->callback([&g, &selected, a] {
    selected = [&g, a] {
      if (a->format != "json" && a->format != "md")
        throw InputError(fmt::format("--format must be json or md, not '{}'", a->format));
      const auto scene = analysis::read_scene(a->scene);
      const auto costs = analysis::load_model_costs(a->costs);
      GlobalOptions run = g;
      if (!scene.space.empty()) run.settings.space = scene.space;
      const auto ctx = [&] {
        try {
          return make_context(run);
        } catch (const InputError& e) {
          if (scene.space.empty()) throw;
          throw InputError(scene.path, scene.space_line, e.what());
        }
      }();
      const auto ms = analysis::load_scene_materials(ctx, scene);
      print_warnings(g, ms);
      const auto studies = analysis::study_materials(ctx, ms, {}, study_progress(g, "plan: fitting "));
      const auto p = analysis::make_plan(scene, ctx, studies, costs);
      fmt::print("{}", a->format == "json" ? report::plan_json(p) : report::plan_markdown(p, costs.source));
      return 0;
    };
  });
}

}  // namespace fl::cli
