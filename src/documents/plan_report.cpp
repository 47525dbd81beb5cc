#include "documents/plan_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "analysis/lut/lut_layout.h"
#include "analysis/plan/reference.h"
#include "documents/plan_text.h"
#include "documents/table_formats.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"

namespace fl::documents {
namespace plan_text {

using analysis::Lighting;

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

std::string served(const analysis::PlanChoice& c, Lighting l) {
  const fresnel::Model m = c.model;
  const auto& s = analysis::lighting_support(m, l);
  if (l == Lighting::Punctual) return "exact at v·h";
  if (!c.roughness.empty() &&
      std::all_of(c.roughness.begin(), c.roughness.end(), [](double r) { return r == 0.0; }))
    return "mirror: F(n·v)";
  return s.fresnel_pre_integrated ? "tables" : fmt::format("F({}) × lobe", s.evaluated_at);
}

std::string error_name(const analysis::PlanChoice& c) {
  return c.error_lighting == Lighting::Punctual
             ? "curve (punctual)"
             : fmt::format("rendered ({})", analysis::lighting_name(c.error_lighting));
}

std::string gpu_text(const std::optional<int>& c) {
  return c ? std::to_string(*c) : std::string(analysis::kUnmeasured);
}
std::vector<std::string> channel_list(const std::vector<analysis::PlanLut>& luts) {
  std::vector<std::string> out;
  for (const auto& l : luts)
    for (const auto& c : l.channels) out.push_back(l.name + " " + c);
  return out;
}

std::string params_text(const analysis::PlanChoice& m) {
  const auto names = fresnel::model_spec(m.model).param_names();
  std::vector<std::string> params;
  for (size_t k = 0; k < names.size(); ++k)
    params.push_back(fmt::format("{} {}", names[k], format_number(m.params[k], 4)));
  return join(params, ", ");
}

}  // namespace plan_text

using namespace plan_text;

namespace {

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
    s += fmt::format(" {} ({}) |", format_number(error_under(m, l), kErrorDecimals), served(m, l));
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

std::string kib_text(long bytes) {
  return format_number(bytes / 1024.0, 0) + " KiB";
}

std::string cost_text(const analysis::SceneCost& c) {
  return fmt::format(
      "{} GPU instructions and {} texture fetches per draw, {} of tables, {} shader "
      "variant{}",
      gpu_text(c.gpu_instructions), gpu_text(c.texture_fetches), kib_text(c.table_bytes),
      c.variants, c.variants > 1 ? "s" : "");
}

// The chosen option in a sentence.
std::string choice_sentence(const analysis::Plan& p) {
  const auto& sc = p.scene_choice();
  std::string s = sc.meets_every_budget()
                      ? fmt::format("**{}** meets every material's budget", sc.name)
                      : fmt::format(
                            "No option meets every budget; **{}** has the smallest worst "
                            "error (over budget: {})",
                            sc.name, join(sc.failing, ", "));
  s += fmt::format(" (worst RMS ΔE2000 {}, median {}). Cost: {}", format_number(sc.worst_de00, 3),
                   format_number(sc.median_de00, 3), cost_text(sc.cost));
  if (sc.cost.variants > 1)
    s += " — shaded as material permutations: each group's model is its own shader variant and a "
         "draw runs its material's (no branch)";
  return s + fmt::format(
                 ". Shader: `fresnel-lab plan {} --shader`; everything for the engine: "
                 "`fresnel-lab plan {} --out DIR`.\n\n",
                 p.scene.path, p.scene.path);
}

std::string group_of(const analysis::SceneOption& o, size_t k) {
  for (const auto& g : o.groups)
    if (std::find(g.materials.begin(), g.materials.end(), k) != g.materials.end()) return g.name;
  return "";
}

std::string scene_markdown(const analysis::Plan& p) {
  const auto& sc = p.scene_choice();
  std::string s = "## The shader set for the scene\n\n" + choice_sentence(p);
  std::string rule = "|---|---|---|---|";
  s += "| group | model | material | parameters |";
  for (Lighting l : p.scene.lightings()) {
    s += fmt::format(" {} rms_de00 |", analysis::lighting_name(l));
    rule += "---|";
  }
  s += " error used | within budget | F_avg (r, g, b) | params | tables read |\n" + rule +
       "---|---|---|---|---|\n";
  for (size_t k = 0; k < sc.materials.size(); ++k) {
    const auto& m = sc.materials[k];
    const bool mirror = p.scene.materials.at(k).mirror();
    const auto tables = channel_list(analysis::material_luts(p, k));
    s += fmt::format("| {} | {} | {} | {} |{} {} | {} | {} | {} | {} |\n", group_of(sc, k),
                     fresnel::model_spec(m.model).name, m.material,
                     analysis::parameter_set_name(m.set), lighting_cells(p.scene, m), error_name(m),
                     m.meets_budget ? "yes" : "**no**", f_avg_text(m.f_avg), params_text(m),
                     mirror           ? "none (roughness 0: a mirror, the model at n·v)"
                     : tables.empty() ? "none"
                                      : join(tables, ", "));
  }
  s += "\nTables for these shaders:\n\n" + luts_markdown(p.scene_luts);
  if (!p.scene_luts.empty())
    s += fmt::format(
        "\nTable size and storage: {0}² texels of {1}, {2} in all ({3}), worst rendered RMS "
        "ΔE2000 {4} with them.\n",
        p.tables.size,
        p.tables.storage == analysis::TexelStorage::Half ? "half floats" : "32-bit floats",
        kib_text(p.tables.bytes),
        p.tables.forced ? "the size given by --lut-size"
                        : "the fewest bytes of 16² to 128², half or float, that keep every "
                          "material within the larger of its budget and its error with 64² "
                          "floats",
        format_number(p.tables.worst_de00, 3));
  return s;
}

std::string option_status(const analysis::Plan& p, size_t i) {
  const auto& o = p.scene_options[i];
  if (i == p.chosen) return "**chosen**";
  if (!o.dominated_by) return "front";
  const auto& d = p.scene_options.at(*o.dominated_by);
  return fmt::format("dominated by {}: costs {} and errs {} at worst ({} vs {})", d.name,
                     analysis::scene_cost_less(d.cost, o.cost) ? "less" : "the same",
                     d.worst_de00 < o.worst_de00 ? "less" : "as much",
                     format_number(d.worst_de00, 3), format_number(o.worst_de00, 3));
}

// Every option considered, the front first (cheapest first), then the dominated ones.
std::string options_markdown(const analysis::Plan& p) {
  std::vector<size_t> order(p.scene_options.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const auto &x = p.scene_options[a], &y = p.scene_options[b];
    if (x.dominated_by.has_value() != y.dominated_by.has_value()) return !x.dominated_by;
    if (analysis::scene_cost_less(x.cost, y.cost) || analysis::scene_cost_less(y.cost, x.cost))
      return analysis::scene_cost_less(x.cost, y.cost);
    return x.worst_de00 < y.worst_de00;
  });
  std::string s =
      "\n## Every option: the Pareto front and the rest\n\n| option | GPU instructions | texture "
      "fetches | tables | variants | worst ΔE2000 | median ΔE2000 | meets every budget | status "
      "|\n|---|---|---|---|---|---|---|---|---|\n";
  for (size_t i : order) {
    const auto& o = p.scene_options[i];
    s += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", o.name,
                     gpu_text(o.cost.gpu_instructions), gpu_text(o.cost.texture_fetches),
                     kib_text(o.cost.table_bytes), o.cost.variants, format_number(o.worst_de00, 3),
                     format_number(o.median_de00, 3), o.meets_every_budget() ? "yes" : "no",
                     option_status(p, i));
  }
  return s +
         "\nCost, compared in this order: GPU instructions per draw (the dearest shader variant, "
         "its "
         "functions for the scene's lightings summed), texture fetches per draw, the bytes of "
         "every "
         "table texture read (each once, 64² half floats), the number of shader variants. An "
         "option is dominated when another costs no more and has no larger worst error, and is "
         "cheaper or more accurate. The plan takes the cheapest option meeting every budget, or, "
         "when none does, the smallest worst error, then the cheapest.\n";
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
  s += scene_markdown(p) + options_markdown(p);
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
      "{}° of what the engine computes from the 64² float tables (`tables`: the Fresnel term "
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

std::string plan_shader(const analysis::Plan& p, const analysis::ShaderDocument& doc) {
  const auto& sc = p.scene_choice();
  if (sc.groups.size() == 1) return plan_group_shader(p, sc.groups.front(), doc);
  if (doc.standalone)
    throw InputError(fmt::format(
        "--standalone prints one shader, and the plan's option '{}' is {} shader variants: print "
        "the include (without --standalone) or write one per group with --out DIR",
        sc.name, sc.groups.size()));
  std::string s = fmt::format(
      "// fresnel-lab plan {}: option '{}', one shader variant per group (material permutations); "
      "define one of the groups' macros to compile its variant.\n",
      p.scene.path, sc.name);
  for (const auto& g : sc.groups)
    s += fmt::format("#ifdef {}\n{}#endif\n", group_macro(g.name), plan_group_shader(p, g, doc));
  return s;
}

std::string group_macro(const std::string& group) {
  std::string out = "FRESNEL_GROUP_";
  for (unsigned char c : group) out += std::isalnum(c) ? static_cast<char>(std::toupper(c)) : '_';
  return out;
}

std::string plan_group_shader(const analysis::Plan& p, const analysis::OptionGroup& g,
                              analysis::ShaderDocument doc) {
  const auto& sc = p.scene_choice();
  doc.notes.push_back(fmt::format("Plan {}: option '{}'; group '{}' ({} material(s)) under {}: {}.",
                                  p.scene.path, sc.name, g.name, g.materials.size(),
                                  join(lighting_list(p.scene), ", "),
                                  fresnel::model_spec(g.model).name));
  for (size_t k : g.materials) {
    const auto& m = sc.materials.at(k);
    doc.notes.push_back(fmt::format("  {} ({}{}): {}", m.material,
                                    analysis::parameter_set_name(m.set),
                                    m.meets_budget ? "" : ", over budget", params_text(m)));
  }
  // A mirror (roughness 0) is the model at n·v, with no table: its function comes along.
  auto lightings = p.scene.lightings();
  const bool mirror = std::any_of(g.materials.begin(), g.materials.end(),
                                  [&](size_t k) { return p.scene.materials.at(k).mirror(); });
  if (mirror && !p.scene.punctual) lightings.insert(lightings.begin(), Lighting::Punctual);
  return analysis::shader_document(g.model, lightings, doc);
}

std::string plan_include_name(const analysis::Plan& p, const analysis::OptionGroup& g,
                              const std::string& ext) {
  if (p.scene_choice().groups.size() == 1) return "fresnel." + ext;
  std::string name = "fresnel_";
  for (unsigned char c : g.name) name += std::isalnum(c) ? static_cast<char>(std::tolower(c)) : '_';
  return name + "." + ext;
}

}  // namespace fl::documents
