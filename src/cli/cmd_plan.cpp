// `plan SCENE.yaml`: the cheapest Fresnel model per scene material within a ΔE2000 budget, and the
// lookup tables the chosen models need under the scene's lighting.
#include <fmt/format.h>

#include <memory>

#include "analysis/plan.h"
#include "cli/app.h"
#include "cli/costs.h"
#include "report/writer.h"
#include "spectral/errors.h"

namespace fl::cli {
namespace {

using report::format_number;
using report::json_escape;

constexpr int kParamDecimals = 6, kErrorDecimals = 3, kCostDecimals = 2;

std::vector<std::string> lighting_list(const analysis::Scene& s) {
  std::vector<std::string> out;
  if (s.punctual) out.push_back("punctual");
  if (s.ibl) out.push_back("ibl");
  if (s.area) out.push_back("area");
  return out;
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (const auto& x : v) out += (out.empty() ? "" : sep) + x;
  return out;
}

std::string plan_json(const analysis::Plan& p) {
  std::string s = "{\n";
  s += fmt::format("  \"scene\": \"{}\",\n", json_escape(p.scene.path));
  s += fmt::format("  \"space\": \"{}\",\n", json_escape(p.space));
  s += fmt::format("  \"max_de00\": {},\n", format_number(p.scene.max_de00, kErrorDecimals));
  std::vector<std::string> quoted;
  for (const auto& l : lighting_list(p.scene)) quoted.push_back("\"" + l + "\"");
  s += fmt::format("  \"lighting\": [{}],\n", join(quoted, ", "));
  s += "  \"materials\": [";
  for (size_t i = 0; i < p.materials.size(); ++i) {
    const auto& m = p.materials[i];
    const auto& spec = fresnel::model_spec(m.model);
    const auto names = spec.param_names();
    std::vector<std::string> params;
    for (size_t k = 0; k < names.size(); ++k)
      params.push_back(fmt::format("\"{}\": {}", names[k], format_number(m.params[k], kParamDecimals)));
    s += fmt::format(
        "{}\n    {{\"material\": \"{}\", \"model\": \"{}\", \"parameters\": \"{}\", \"params\": {{{}}}, "
        "\"rms_de00\": {}, \"ns_per_eval\": {}, \"meets_budget\": {}}}",
        i ? "," : "", json_escape(m.material), spec.name, m.fitted ? "fitted" : "derived", join(params, ", "),
        format_number(m.rms_de00, kErrorDecimals), format_number(m.ns_per_eval, kCostDecimals),
        m.meets_budget ? "true" : "false");
  }
  s += "\n  ],\n  \"luts\": [";
  for (size_t i = 0; i < p.luts.size(); ++i) {
    const auto& l = p.luts[i];
    std::vector<std::string> ch;
    for (const auto& c : l.channels) ch.push_back("\"" + c + "\"");
    s += fmt::format("{}\n    {{\"name\": \"{}\", \"lighting\": \"{}\", \"channels\": [{}], \"command\": \"{}\"}}",
                     i ? "," : "", l.name, l.lighting, join(ch, ", "), json_escape(l.command));
  }
  s += p.luts.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return s;
}

std::string plan_markdown(const analysis::Plan& p, const std::string& cost_source) {
  std::string s = fmt::format("# Fresnel plan for {}\n\n", p.scene.path);
  s += fmt::format("Budget: RMS ΔE2000 ≤ {} per material; working space {}; lighting: {}.\n\n",
                   format_number(p.scene.max_de00, kErrorDecimals), p.space, join(lighting_list(p.scene), ", "));
  s += "| material | model | parameters | rms_de00 | ns_per_eval | within budget | params |\n";
  s += "|---|---|---|---|---|---|---|\n";
  int unserved = 0;
  for (const auto& m : p.materials) {
    const auto& spec = fresnel::model_spec(m.model);
    const auto names = spec.param_names();
    std::vector<std::string> params;
    for (size_t k = 0; k < names.size(); ++k)
      params.push_back(fmt::format("{} {}", names[k], format_number(m.params[k], 4)));
    unserved += !m.meets_budget;
    s += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", m.material, spec.name, m.fitted ? "fitted" : "derived",
                     format_number(m.rms_de00, kErrorDecimals), format_number(m.ns_per_eval, kCostDecimals),
                     m.meets_budget ? "yes" : "**no** (best model shown)", join(params, ", "));
  }
  s += "\n## Lookup tables\n\n";
  if (p.luts.empty()) s += "None: punctual lights evaluate the Fresnel model directly.\n";
  for (const auto& l : p.luts)
    s += fmt::format("- `{}` ({}): {} — `{}`\n", l.name, l.lighting, join(l.channels, ", "), l.command);
  s += fmt::format("\nThe cheapest model (cost: {}) whose RMS ΔE2000 against spectral ground truth meets the budget, "
                   "from derived and fitted parameter sets.{}\n",
                   cost_source,
                   unserved ? fmt::format(" {} material(s) cannot be served within the budget by any model.", unserved)
                            : std::string());
  return s;
}

void add_plan(CLI::App& app, GlobalOptions& g, Runner& selected) {
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
      const auto costs = load_model_costs(a->costs);
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
      analysis::StudyOptions o;
      const auto studies = analysis::study_materials(ctx, ms, o, [&g](int done, int total) {
        if (!g.quiet) fmt::print(stderr, "\rplan: fitting {}/{} materials{}", done, total, done == total ? "\n" : "");
      });
      const auto p = analysis::make_plan(scene, ctx, studies, costs);
      fmt::print("{}", a->format == "json" ? plan_json(p) : plan_markdown(p, costs.source));
      return 0;
    };
  });
}

}  // namespace

void add_plan_command(CLI::App& app, GlobalOptions& g, Runner& selected) { add_plan(app, g, selected); }

}  // namespace fl::cli
