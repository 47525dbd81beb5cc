#include "analysis/plan.h"

#include <algorithm>
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

std::vector<PlanLut> needed_luts(const Scene& scene, const std::vector<PlanChoice>& choices) {
  std::vector<PlanLut> out;
  if (scene.ibl)
    out.push_back({"dfg", "ibl", {"dfg1", "dfg2"}, "fresnel-lab lut dfg --out dfg.exr"});
  if (scene.area) {
    out.push_back({"ltc_matrix", "area", {"inv_m00", "inv_m20", "inv_m02", "inv_m22"},
                   "fresnel-lab lut ltc --out ltc.exr (ltc_1.exr)"});
    out.push_back({"ltc_moments", "area", {"n_d", "f_d"}, "fresnel-lab lut ltc --out ltc.exr (ltc_2.exr R, G)"});
    const bool f82 = std::any_of(choices.begin(), choices.end(), [](const PlanChoice& c) { return c.model == Model::F82; });
    if (f82)
      out.push_back({"ltc_f82_moment", "area", {"l_d"}, "fresnel-lab lut ltc --out ltc.exr (ltc_2.exr B)"});
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
