// `plan SCENE.yaml`: the cheapest Fresnel model per scene material within a ΔE2000 budget as
// rendered under the scene's lighting, the shader set for the scene, and the lookup tables they
// need.
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include "analysis/plan/plan.h"
#include "analysis/plan/reference.h"
#include "cli/app.h"
#include "documents/plan_report.h"
#include "draw/plan_plot.h"
#include "jobs/plan_files.h"
#include "util/errors.h"

namespace fl::cli {
namespace {

// `--shader [--lang L] [--size N] [--standalone]`: the chosen shader set's document.
struct ShaderArgs {
  bool shader = false, standalone = false;
  std::string lang = "glsl";
  int size = analysis::kEngineLutSize;
};

void add_shader_options(CLI::App* sub, ShaderArgs& s) {
  sub->add_flag("--shader", s.shader, "print the chosen shader set's include instead of the plan");
  sub->add_option("--lang", s.lang, "with --shader: glsl or hlsl")->capture_default_str();
  sub->add_option("--size", s.size,
                  "with --shader: texels per axis of the tables the shader samples (`lut --size`)")
      ->capture_default_str();
  sub->add_flag("--standalone", s.standalone,
                "with --shader: a complete fragment shader around the include");
}

// The options checked (InputError), as plan_shader's request.
analysis::ShaderDocument shader_document(const std::string& scene, const ShaderArgs& s) {
  analysis::check_lut_size(s.size);
  return {analysis::shader_language_from_name(s.lang),
          s.size,
          s.standalone,
          fmt::format("fresnel-lab plan {} --shader --lang {} --size {}{}", scene, s.lang, s.size,
                      s.standalone ? " --standalone" : ""),
          {}};
}

struct PlanArgs {
  std::string scene, format = "md", costs, gpu_costs, out, plot;
  int lut_size = 0;  // 0: chosen by the budget
  ShaderArgs shader;
};

int run_plan(const GlobalOptions& g, const PlanArgs& a) {
  if (a.format != "json" && a.format != "md")
    throw InputError(fmt::format("--format must be json or md, not '{}'", a.format));
  const auto shader = shader_document(a.scene, a.shader);
  const auto& sizes = analysis::kPlanLutSizes;
  if (a.lut_size != 0 && std::find(sizes.begin(), sizes.end(), a.lut_size) == sizes.end())
    throw InputError(fmt::format("--lut-size must be 16, 32, 64 or 128, not {}", a.lut_size));
  if (!a.plot.empty()) draw::file_type(a.plot);  // an unknown extension, before the work
  if (!a.out.empty()) io::require_replaceable_folder(a.out, jobs::kPlanMarker);
  auto scene = analysis::read_scene(a.scene);
  const analysis::PlanCosts costs{
      analysis::load_model_costs(given_or(a.costs, g.settings.paths.model_costs)),
      analysis::load_gpu_costs(given_or(a.gpu_costs, g.settings.paths.gpu_costs))};
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
  for (const auto& note : scene.notes) progress(g, "note: " + note);
  print_warnings(g, ms);
  const auto studies = analysis::study_materials(ctx, ms, {}, study_progress(g, "plan: fitting "));
  progress(g, "plan: choosing the shaders and the tables' size");
  const auto p = analysis::make_plan(scene, ctx, studies, costs, a.lut_size);
  std::optional<draw::LabelFont> font;
  if (!a.plot.empty() || !a.out.empty()) font.emplace(g.label_font);
  if (!a.plot.empty()) draw::write_drawing(a.plot, draw::plan_plot(p), *font);
  if (!a.out.empty()) {
    std::map<std::string, std::function<void(int, int)>> bars;  // one labelled bar per table
    const auto table_progress = [&](const std::string& table, int done, int total) {
      auto& bar = bars[table];
      if (!bar) bar = periodic_progress(g, "plan: " + table + " cells ", 2);
      bar(done, total);
    };
    io::replace_folder_atomic(a.out,
                              jobs::plan_files(p, costs, analysis::plan_reference(ctx, studies, p),
                                               *font, 0, table_progress),
                              jobs::kPlanMarker);
    progress(g, fmt::format("plan: wrote {} ({})", a.out, p.scene_choice().name));
    return 0;
  }
  if (a.shader.shader)
    fmt::print("{}", documents::plan_shader(p, shader));
  else
    fmt::print("{}",
               a.format == "json" ? documents::plan_json(p) : documents::plan_markdown(p, costs));
  return 0;
}

}  // namespace

void add_plan_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("plan",
                                 "per scene material the cheapest Fresnel model within a ΔE2000 "
                                 "budget, and the lookup tables it needs");
  auto a = std::make_shared<PlanArgs>();
  sub->add_option("SCENE", a->scene,
                  "scene YAML: materials (list; an entry may be {name, roughness}), max_de00 "
                  "(default 1.0), space, "
                  "lighting (punctual, ibl, area), roughness")
      ->required();
  sub->add_option("--format", a->format, "json or md")->capture_default_str();
  sub->add_option(
      "--costs", a->costs,
      "model costs file (default $FRESNEL_LAB_COSTS or the tool's bench/model_costs.csv)");
  sub->add_option(
      "--gpu-costs", a->gpu_costs,
      "GPU costs file (default $FRESNEL_LAB_GPU_COSTS or the tool's bench/gpu_costs.csv)");
  sub->add_option("--lut-size", a->lut_size,
                  "texels per axis of the tables the plan writes (16, 32, 64 or 128; default: the "
                  "fewest bytes that keep every material within its budget)");
  add_shader_options(sub, a->shader);
  sub->add_option("--out", a->out,
                  "write everything the engine needs into this folder: the shader includes, the "
                  "tables they read, materials.json, README.md, the plan and its figure")
      ->check(output_location());
  sub->add_option("--plot", a->plot,
                  "also draw the options' cost against error (FILE.png, FILE.svg or FILE.pdf)")
      ->check(output_location());
  sub->callback([&g, &selected, a] { selected = [&g, a] { return run_plan(g, *a); }; });
}

}  // namespace fl::cli
