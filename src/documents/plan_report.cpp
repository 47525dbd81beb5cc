#include "documents/plan_report.h"

#include <fmt/format.h>

#include "documents/json.h"
#include "documents/table_formats.h"
#include "fresnel/registered_models.h"

namespace fl::report {
namespace {

using analysis::Lighting;

constexpr int kParamDecimals = 6, kErrorDecimals = 3, kCostDecimals = 2;

std::vector<std::string> lighting_list(const analysis::Scene& s) {
  std::vector<std::string> out;
  for (Lighting l : s.lightings()) out.push_back(analysis::lighting_name(l));
  return out;
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (const auto& x : v) out += (out.empty() ? "" : sep) + x;
  return out;
}

double error_under(const analysis::PlanChoice& c, Lighting l) {
  return l == Lighting::Ibl ? c.ibl_rms : l == Lighting::Area ? c.area_rms : c.punctual_rms;
}

// How the engine shades the model under l: "tables" or the named approximation.
std::string served(fresnel::Model m, Lighting l) {
  const auto& s = analysis::lighting_support(m, l);
  if (l == Lighting::Punctual) return "exact at v·h";
  return s.fresnel_pre_integrated ? "tables" : fmt::format("F({}) × lobe", s.evaluated_at);
}

std::string error_name(const analysis::PlanChoice& c) {
  return c.error_lighting == Lighting::Punctual
             ? "curve (punctual)"
             : fmt::format("rendered ({})", analysis::lighting_name(c.error_lighting));
}

// A cost, or "unmeasured" (no row in the cost file).
template <class T>
Json cost_json(const std::optional<T>& c) {
  return c ? Json(*c) : Json(analysis::kUnmeasured);
}
std::string gpu_text(const std::optional<int>& c) {
  return c ? std::to_string(*c) : std::string(analysis::kUnmeasured);
}
std::string cpu_text(const std::optional<double>& c) {
  return c ? format_number(*c, kCostDecimals) : std::string(analysis::kUnmeasured);
}

Json params_json(const analysis::PlanChoice& m) {
  const auto names = fresnel::model_spec(m.model).param_names();
  Json params = Json::object();
  for (size_t k = 0; k < names.size(); ++k) params[names[k]] = m.params[k];
  return params;
}

Json choice_json(const analysis::Scene& scene, const analysis::PlanChoice& m) {
  Json errors = Json::object(), how = Json::object();
  for (Lighting l : scene.lightings()) {
    errors[analysis::lighting_name(l)] = error_under(m, l);
    how[analysis::lighting_name(l)] = served(m.model, l);
  }
  return {{"material", m.material},
          {"model", fresnel::model_spec(m.model).name},
          {"parameters", analysis::parameter_set_name(m.set)},
          {"params", params_json(m)},
          {"roughness", m.roughness},
          {"rms_de00", errors},
          {"shading", how},
          {"error_used",
           {{"lighting", analysis::lighting_name(m.error_lighting)}, {"rms_de00", m.error}}},
          {"gpu_instructions", cost_json(m.gpu_instructions)},
          {"cpu_ns_per_eval", cost_json(m.ns_per_eval)},
          {"meets_budget", m.meets_budget},
          {"f_avg", {m.f_avg.r, m.f_avg.g, m.f_avg.b}}};
}

Json luts_json(const std::vector<analysis::PlanLut>& luts) {
  Json out = Json::array();
  for (const auto& l : luts)
    out.push_back({{"name", l.name},
                   {"lighting", l.lighting},
                   {"file", l.file},
                   {"channels", l.channels},
                   {"command", l.command}});
  return out;
}

}  // namespace

std::string plan_json(const analysis::Plan& p) {
  Json materials = Json::array(), scene_materials = Json::array();
  for (const auto& m : p.materials) materials.push_back(choice_json(p.scene, m));
  for (const auto& m : p.scene_choice.materials) scene_materials.push_back(choice_json(p.scene, m));
  const auto& sc = p.scene_choice;
  Json doc = {{"scene", p.scene.path},
              {"space", p.space},
              {"max_de00", p.scene.max_de00},
              {"lighting", lighting_list(p.scene)},
              {"materials", std::move(materials)},
              {"luts", luts_json(p.luts)},
              {"scene_shader",
               {{"model", fresnel::model_spec(sc.model).name},
                {"meets_every_budget", sc.failing.empty()},
                {"failing", sc.failing},
                {"gpu_instructions", cost_json(sc.gpu_instructions)},
                {"cpu_ns_per_eval", cost_json(sc.ns_per_eval)},
                {"materials", std::move(scene_materials)},
                {"luts", luts_json(p.scene_luts)}}}};
  if (!p.unmeasured.empty()) doc["unmeasured"] = p.unmeasured;
  return write_json(doc, [](const std::string& key) {
    if (key == "max_de00" || key == "rms_de00" || key == "punctual" || key == "ibl" ||
        key == "area" || key == "roughness")
      return kErrorDecimals;
    if (key == "cpu_ns_per_eval") return kCostDecimals;
    return kParamDecimals;  // the members of "params", f_avg
  });
}

namespace {

std::string params_text(const analysis::PlanChoice& m) {
  const auto names = fresnel::model_spec(m.model).param_names();
  std::vector<std::string> params;
  for (size_t k = 0; k < names.size(); ++k)
    params.push_back(fmt::format("{} {}", names[k], format_number(m.params[k], 4)));
  return join(params, ", ");
}

std::string f_avg_text(const color::Rgb& f) {
  return fmt::format("{}, {}, {}", format_number(f.r, 4), format_number(f.g, 4),
                     format_number(f.b, 4));
}

std::string luts_markdown(const std::vector<analysis::PlanLut>& luts) {
  if (luts.empty()) return "None: punctual lights evaluate the Fresnel model directly.\n";
  std::string s;
  for (const auto& l : luts)
    s += fmt::format("- `{}` ({}): {} — `{}`\n", l.file, l.lighting, join(l.channels, ", "),
                     l.command);
  return s;
}

// "| ibl | area |" cells: each lighting's error and how the engine shades it.
std::string lighting_cells(const analysis::Scene& scene, const analysis::PlanChoice& m) {
  std::string s;
  for (Lighting l : scene.lightings())
    s += fmt::format(" {} ({}) |", format_number(error_under(m, l), kErrorDecimals),
                     served(m.model, l));
  return s;
}

std::string table_header(const analysis::Scene& scene, bool with_model) {
  std::string head = with_model ? "| material | model | parameters |" : "| material | parameters |";
  std::string rule = with_model ? "|---|---|---|" : "|---|---|";
  for (Lighting l : scene.lightings()) {
    head += fmt::format(" {} rms_de00 |", analysis::lighting_name(l));
    rule += "---|";
  }
  head += " error used | within budget | F_avg (r, g, b) | params |\n";
  rule += "---|---|---|---|\n";
  return head + rule;
}

std::string scene_markdown(const analysis::Plan& p) {
  const auto& sc = p.scene_choice;
  const auto& spec = fresnel::model_spec(sc.model);
  std::string s = "## One shader for the scene\n\n";
  s += sc.failing.empty()
           ? fmt::format("**{}** meets every material's budget", spec.name)
           : fmt::format("No single model meets every budget; **{}** fails fewest ({}: {})",
                         spec.name, sc.failing.size(), join(sc.failing, ", "));
  s += fmt::format(
      ". Cost: {} GPU instructions ({}), {} CPU ns per evaluation. Shader: `fresnel-lab plan {} "
      "--shader`.\n\n",
      gpu_text(sc.gpu_instructions), join(lighting_list(p.scene), " + "), cpu_text(sc.ns_per_eval),
      p.scene.path);
  s += table_header(p.scene, false);
  for (const auto& m : sc.materials)
    s += fmt::format("| {} | {} |{} {} | {} | {} | {} |\n", m.material,
                     analysis::parameter_set_name(m.set), lighting_cells(p.scene, m), error_name(m),
                     m.meets_budget ? "yes" : "**no**", f_avg_text(m.f_avg), params_text(m));
  s += "\nTables for this shader:\n\n" + luts_markdown(p.scene_luts);
  return s;
}

}  // namespace

std::string plan_markdown(const analysis::Plan& p, const analysis::PlanCosts& costs) {
  std::string roughness;
  for (double r : p.scene.roughness)
    roughness += (roughness.empty() ? "" : ", ") + fmt::format("{:g}", r);
  std::string s = fmt::format("# Fresnel plan for {}\n\n", p.scene.path);
  s += fmt::format(
      "Budget: RMS ΔE2000 ≤ {} per material, as rendered under the scene's lighting ({}); working "
      "space "
      "{}; roughness {} unless a material sets its own.\n\n",
      format_number(p.scene.max_de00, kErrorDecimals), join(lighting_list(p.scene), ", "), p.space,
      roughness);
  s += scene_markdown(p);
  s += "\n## Per material\n\n" + table_header(p.scene, true);
  int unserved = 0;
  for (const auto& m : p.materials) {
    unserved += !m.meets_budget;
    s += fmt::format(
        "| {} | {} | {} |{} {} | {} | {} | {} |\n", m.material, fresnel::model_spec(m.model).name,
        analysis::parameter_set_name(m.set), lighting_cells(p.scene, m), error_name(m),
        m.meets_budget ? "yes" : "**no** (best model shown)", f_avg_text(m.f_avg), params_text(m));
  }
  s += "\nTables for the per-material choices:\n\n" + luts_markdown(p.luts);
  s += fmt::format(
      "\nPer material the cheapest model (GPU instructions of its shader functions for the scene's "
      "lighting, from {}; "
      "then CPU ns, from {}) whose error meets the budget, from derived, fitted (to the curve) and "
      "rendered (fitted to the "
      "render at the scene's roughness) parameter sets. "
      "Errors: the curve's "
      "RMS ΔE2000 under punctual lights; under ibl and area the RMS ΔE2000 over the roughness "
      "values × view angles "
      "{}° of what the engine computes from the 64² tables (`tables`: the Fresnel term "
      "pre-integrated; `F(n·v) × "
      "lobe`: the stated approximation for models no shared table holds) against brute-force "
      "spectral integration of "
      "the GGX lobe; the budget applies to the largest (error used). F_avg = 2∫F(μ)μ dμ per "
      "channel, for "
      "Kulla–Conty energy compensation.{}\n",
      costs.gpu.source, costs.cpu.source, "0, 30, 50, 65, 75, 85",
      unserved ? fmt::format(" {} material(s) cannot be served within the budget by any model.",
                             unserved)
               : std::string());
  if (!p.unmeasured.empty())
    s += fmt::format(
        "\nUnmeasured cost (no row in a cost file; scripts/bench.sh and scripts/gpu_costs.sh "
        "measure them): {}. Their cost is unknown, so they rank after every measured model.\n",
        join(p.unmeasured, ", "));
  return s;
}

std::string plan_shader(const analysis::Plan& p, analysis::ShaderDocument doc) {
  const auto& sc = p.scene_choice;
  doc.notes.push_back(fmt::format(
      "Plan {}: one shader for {} material(s) under {}: {}{}.", p.scene.path, sc.materials.size(),
      join(lighting_list(p.scene), ", "), fresnel::model_spec(sc.model).name,
      sc.failing.empty() ? "" : fmt::format(" (over budget: {})", join(sc.failing, ", "))));
  for (const auto& m : sc.materials)
    doc.notes.push_back(fmt::format("  {} ({}): {}", m.material,
                                    analysis::parameter_set_name(m.set), params_text(m)));
  return analysis::shader_document(sc.model, p.scene.lightings(), doc);
}

}  // namespace fl::report
