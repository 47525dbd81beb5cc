#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "analysis/lut/lut_layout.h"
#include "analysis/plan/reference.h"
#include "documents/json.h"
#include "documents/plan_report.h"
#include "documents/plan_text.h"
#include "documents/table_formats.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"

namespace fl::documents {

using namespace plan_text;
using analysis::Lighting;

namespace {

// A cost, or "unmeasured" (no row in the cost file).
template <class T>
Json cost_json(const std::optional<T>& c) {
  return c ? Json(*c) : Json(analysis::kUnmeasured);
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
    how[analysis::lighting_name(l)] = served(m, l);
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

namespace {

Json groups_json(const analysis::SceneOption& o) {
  Json out = Json::array();
  for (const auto& g : o.groups) {
    Json materials = Json::array(), parameters = Json::array();
    for (size_t k : g.materials) {
      const auto& m = o.materials.at(k);
      materials.push_back(m.material);
      parameters.push_back({{"material", m.material},
                            {"set", analysis::parameter_set_name(m.set)},
                            {"params", params_json(m)}});
    }
    out.push_back({{"name", g.name},
                   {"materials", std::move(materials)},
                   {"model", fresnel::model_spec(g.model).name},
                   {"parameters", std::move(parameters)}});
  }
  return out;
}

Json option_json(const std::vector<analysis::SceneOption>& all, const analysis::SceneOption& o) {
  return {{"name", o.name},
          {"grouping", o.grouping},
          {"groups", groups_json(o)},
          {"gpu_instructions", cost_json(o.cost.gpu_instructions)},
          {"texture_fetches", cost_json(o.cost.texture_fetches)},
          {"table_bytes", o.cost.table_bytes},
          {"shader_variants", o.cost.variants},
          {"worst_de00", o.worst_de00},
          {"median_de00", o.median_de00},
          {"meets_every_budget", o.meets_every_budget()},
          {"failing", o.failing},
          {"dominated_by", o.dominated_by ? Json(all.at(*o.dominated_by).name) : Json(nullptr)}};
}

Json scene_shader_json(const analysis::Plan& p) {
  const auto& sc = p.scene_choice();
  Json materials = Json::array();
  for (size_t k = 0; k < sc.materials.size(); ++k) {
    Json m = choice_json(p.scene, sc.materials[k]);
    m["mirror"] = p.scene.materials.at(k).mirror();
    m["tables"] = channel_list(analysis::material_luts(p, k));
    materials.push_back(std::move(m));
  }
  Json out = {{"option", sc.name}};
  out.update(option_json(p.scene_options, sc));
  out["shading"] = sc.cost.variants > 1 ? "material permutations" : "one shader";
  out["materials"] = std::move(materials);
  out["luts"] = luts_json(p.scene_luts);
  if (!p.scene_luts.empty())
    out["lut_tables"] = {{"size", p.tables.size},
                         {"storage", analysis::texel_storage_name(p.tables.storage)},
                         {"bytes", p.tables.bytes},
                         {"worst_de00", p.tables.worst_de00},
                         {"size_forced", p.tables.forced}};
  return out;
}

}  // namespace

std::string plan_json(const analysis::Plan& p) {
  Json materials = Json::array(), options = Json::array();
  for (const auto& m : p.materials) materials.push_back(choice_json(p.scene, m));
  for (const auto& o : p.scene_options) options.push_back(option_json(p.scene_options, o));
  Json doc = {{"scene", p.scene.path},
              {"space", p.space},
              {"max_de00", p.scene.max_de00},
              {"lighting", lighting_list(p.scene)},
              {"materials", std::move(materials)},
              {"luts", luts_json(p.luts)},
              {"scene_shader", scene_shader_json(p)},
              {"scene_options", std::move(options)}};
  if (!p.unmeasured.empty()) doc["unmeasured"] = p.unmeasured;
  return write_json(doc, [](const std::string& key) {
    if (key == "max_de00" || key == "rms_de00" || key == "punctual" || key == "ibl" ||
        key == "area" || key == "roughness")
      return kErrorDecimals;
    if (key == "cpu_ns_per_eval") return kCostDecimals;
    return kParamDecimals;  // the members of "params", f_avg, worst_de00, median_de00
  });
}

std::string plan_materials_json(const analysis::Plan& p) {
  const auto& sc = p.scene_choice();
  Json materials = Json::array();
  for (const auto& g : sc.groups)
    for (size_t k : g.materials) {
      const auto& m = sc.materials.at(k);
      const auto names = fresnel::model_spec(m.model).param_names();
      Json params = Json::object();
      for (size_t i = 0; i < names.size(); ++i) params[names[i]] = m.params[i];
      std::vector<std::string> tables;
      for (const auto& l : analysis::material_luts(p, k))
        for (const auto& c : l.channels) tables.push_back(l.file + " " + c);
      materials.push_back({{"material", m.material},
                           {"group", g.name},
                           {"include", plan_include_name(p, g, "glsl")},
                           {"model", fresnel::model_spec(m.model).name},
                           {"parameters", analysis::parameter_set_name(m.set)},
                           {"params", params},
                           {"roughness", m.roughness},
                           {"mirror", p.scene.materials.at(k).mirror()},
                           {"tables", tables},
                           {"rendered_de00", m.error},
                           {"meets_budget", m.meets_budget}});
    }
  Json doc = {{"scene", p.scene.path},
              {"option", sc.name},
              {"max_de00", p.scene.max_de00},
              {"materials", materials}};
  return write_json(doc, [](const std::string& key) {
    return key == "max_de00" || key == "roughness" || key == "rendered_de00" ? kErrorDecimals
                                                                             : kParamDecimals;
  });
}

}  // namespace fl::documents
