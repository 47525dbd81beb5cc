#include "analysis/plan/plan.h"

#include <algorithm>
#include <set>
#include <filesystem>

#include "spectral/errors.h"
#include "spectral/scene_file.h"

namespace fl::analysis {

using fresnel::Model;

namespace {

// A material given as a relative file path is looked up next to the scene first.
std::string resolve_relative(const std::string& scene_path, const std::string& spec) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(spec);
  if (p.is_absolute() || fs::exists(p, ec)) return spec;
  const fs::path beside = fs::path(scene_path).parent_path() / p;
  if (fs::is_regular_file(beside, ec)) return beside.string();
  return spec;
}

}  // namespace

Scene read_scene(const std::string& path) {
  const auto f = spectral::read_scene_file(path);
  Scene s;
  s.path = f.path;
  for (const auto& m : f.materials) s.materials.push_back({resolve_relative(path, m.spec), m.line});
  s.max_de00 = f.max_de00.value_or(kDefaultMaxDe00);
  s.space = f.space;
  s.space_line = f.space_line;
  s.punctual = f.punctual || (!f.ibl && !f.area);
  s.ibl = f.ibl;
  s.area = f.area;
  return s;
}

std::vector<LoadedMaterial> load_scene_materials(const Context& ctx, const Scene& scene) {
  std::vector<LoadedMaterial> out;
  for (const auto& m : scene.materials) {
    try {
      out.push_back(load_material(ctx, spectral::resolve_material(m.spec, ctx.settings().paths)));
    } catch (const InputError& e) {
      throw InputError(scene.path, m.line, e.what());
    }
  }
  return out;
}

PlanChoice choose_model(const MaterialStudy& study, const ModelCosts& costs, double max_de00) {
  std::vector<PlanChoice> candidates;
  for (const auto& r : study.models) {
    for (int fitted = 0; fitted < 2; ++fitted) {
      if (fitted && (!r.fitted.usable || r.fitted.parameters.empty())) continue;
      PlanChoice c;
      c.material = study.material->material.name;
      c.model = r.model;
      c.fitted = fitted != 0;
      c.params = fitted ? r.fitted.parameters : r.derived;
      c.rms_de00 = fitted ? r.fitted_error.rms : r.derived_error.rms;
      c.ns_per_eval = costs.ns_per_eval(r.model);
      c.meets_budget = c.rms_de00 <= max_de00;
      candidates.push_back(std::move(c));
    }
  }
  if (candidates.empty()) throw std::logic_error("no model studied");
  // stable_sort keeps model_specs() order (derived before fitted) among exact ties.
  std::stable_sort(candidates.begin(), candidates.end(), [](const PlanChoice& a, const PlanChoice& b) {
    if (a.ns_per_eval != b.ns_per_eval) return a.ns_per_eval < b.ns_per_eval;
    return a.rms_de00 < b.rms_de00;
  });
  for (const auto& c : candidates)
    if (c.meets_budget) return c;
  return *std::min_element(candidates.begin(), candidates.end(),
                           [](const PlanChoice& a, const PlanChoice& b) { return a.rms_de00 < b.rms_de00; });
}

namespace {

// The tables `lut` writes, the model channels (fresnel::lut_channel) each holds, and how to make it.
struct LutSource {
  const char* name;
  const char* lighting;
  std::vector<std::pair<const char*, std::vector<std::string>>> channels;  // model channel → file channels
  const char* command;
};
const std::vector<LutSource>& lut_sources() {
  namespace ch = fresnel::lut_channel;
  static const std::vector<LutSource> sources{
      {"dfg", "ibl", {{ch::kDfgScale, {"dfg1"}}, {ch::kDfgBias, {"dfg2"}}}, "fresnel-lab lut dfg --out dfg.exr (R, G)"},
      {"dfg_f82", "ibl", {{ch::kDfgF82, {"dfg_f82"}}}, "fresnel-lab lut dfg --out dfg.exr (B)"},
      {"ltc_matrix", "area", {{ch::kLtcMatrix, {"inv_m00", "inv_m20", "inv_m02", "inv_m22"}}},
       "fresnel-lab lut ltc --out ltc.exr (ltc_1.exr)"},
      {"ltc_moments", "area", {{ch::kLtcNorm, {"n_d"}}, {ch::kLtcSchlick, {"f_d"}}},
       "fresnel-lab lut ltc --out ltc.exr (ltc_2.exr R, G)"},
      {"ltc_f82_moment", "area", {{ch::kLtcF82, {"l_d"}}}, "fresnel-lab lut ltc --out ltc.exr (ltc_2.exr B)"},
  };
  return sources;
}

}  // namespace

std::vector<PlanLut> needed_luts(const Scene& scene, const std::vector<PlanChoice>& choices) {
  std::set<std::string> needed;  // "lighting/channel", from every chosen model's declaration
  for (const auto& c : choices) {
    const auto& pi = fresnel::model_spec(c.model).pre_integration;
    if (scene.ibl)
      for (const char* ch : pi.ibl.channels) needed.insert(std::string("ibl/") + ch);
    if (scene.area)
      for (const char* ch : pi.area.channels) needed.insert(std::string("area/") + ch);
  }
  std::vector<PlanLut> out;
  for (const auto& src : lut_sources()) {
    PlanLut lut{src.name, src.lighting, {}, src.command};
    for (const auto& [model_channel, file_channels] : src.channels)
      if (needed.count(std::string(src.lighting) + "/" + model_channel))
        lut.channels.insert(lut.channels.end(), file_channels.begin(), file_channels.end());
    if (!lut.channels.empty()) out.push_back(std::move(lut));
  }
  return out;
}

Plan make_plan(const Scene& scene, const Context& ctx, const std::vector<MaterialStudy>& studies,
               const ModelCosts& costs) {
  Plan p;
  p.scene = scene;
  p.space = ctx.settings().space;
  for (const auto& s : studies) p.materials.push_back(choose_model(s, costs, scene.max_de00));
  p.luts = needed_luts(scene, p.materials);
  return p;
}

}  // namespace fl::analysis
