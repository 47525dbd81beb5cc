#include "report/plan_report.h"

#include <fmt/format.h>

#include "report/json.h"
#include "report/writer.h"

namespace fl::report {
namespace {

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

}  // namespace

std::string plan_json(const analysis::Plan& p) {
  Json materials = Json::array();
  for (const auto& m : p.materials) {
    const auto& spec = fresnel::model_spec(m.model);
    const auto names = spec.param_names();
    Json params = Json::object();
    for (size_t k = 0; k < names.size(); ++k) params[names[k]] = m.params[k];
    materials.push_back({{"material", m.material},
                         {"model", spec.name},
                         {"parameters", m.fitted ? "fitted" : "derived"},
                         {"params", std::move(params)},
                         {"rms_de00", m.rms_de00},
                         {"ns_per_eval", m.ns_per_eval},
                         {"meets_budget", m.meets_budget}});
  }
  Json luts = Json::array();
  for (const auto& l : p.luts)
    luts.push_back({{"name", l.name}, {"lighting", l.lighting}, {"channels", l.channels}, {"command", l.command}});
  const Json doc = {{"scene", p.scene.path},
                    {"space", p.space},
                    {"max_de00", p.scene.max_de00},
                    {"lighting", lighting_list(p.scene)},
                    {"materials", std::move(materials)},
                    {"luts", std::move(luts)}};
  return write_json(doc, [](const std::string& key) {
    if (key == "max_de00" || key == "rms_de00") return kErrorDecimals;
    if (key == "ns_per_eval") return kCostDecimals;
    return kParamDecimals;  // the members of "params"
  });
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

}  // namespace fl::report
