#include "analysis/plan/plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "fresnel/average.h"
#include "fresnel/registered_models.h"
#include "spectral/scene_file.h"
#include "util/errors.h"
#include "util/truncated.h"

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

bool SceneMaterial::mirror() const {
  return !roughness.empty() &&
         std::all_of(roughness.begin(), roughness.end(), [](double r) { return r == 0.0; });
}

std::vector<Lighting> Scene::lightings() const {
  std::vector<Lighting> out;
  if (punctual) out.push_back(Lighting::Punctual);
  if (ibl) out.push_back(Lighting::Ibl);
  if (area) out.push_back(Lighting::Area);
  return out;
}

Scene read_scene(const std::string& path) {
  const auto f = spectral::read_scene_file(path);
  Scene s;
  s.path = f.path;
  s.roughness = f.roughness.empty()
                    ? std::vector<double>(kDefaultRoughness.begin(), kDefaultRoughness.end())
                    : f.roughness;
  for (const auto& m : f.materials)
    s.materials.push_back({resolve_relative(path, m.spec), m.line,
                           m.roughness.empty() ? s.roughness : m.roughness, m.group});
  s.max_de00 = f.max_de00.value_or(kDefaultMaxDe00);
  s.space = f.space;
  s.space_line = f.space_line;
  s.punctual = f.punctual || (!f.ibl && !f.area);
  s.ibl = f.ibl;
  s.area = f.area;
  s.notes = f.notes;
  return s;
}

namespace {

// The scene's entries with their page globs expanded, a page given twice merged into its first
// entry; InputError past spectral::kMaxSceneMaterials.
std::vector<std::pair<SceneMaterial, bool>> expand_scene(const Context& ctx, Scene& scene) {
  std::vector<std::pair<SceneMaterial, bool>> out;  // (material, a database page of a glob)
  const auto& paths = ctx.settings().paths;
  for (const auto& m : scene.materials) {
    try {
      for (const auto& r : spectral::expand_materials({m.spec}, paths)) {
        const auto it = std::find_if(out.begin(), out.end(),
                                     [&](const auto& x) { return x.first.spec == r.spec; });
        if (it == out.end()) {
          out.push_back({{r.spec, m.line, m.roughness, m.group}, !r.pattern.empty()});
          continue;
        }
        auto& rs = it->first.roughness;
        for (const double x : m.roughness)
          if (std::find(rs.begin(), rs.end(), x) == rs.end()) rs.push_back(x);
        scene.notes.push_back(fmt::format("{}:{}: '{}' is also given at line {}: merged",
                                          scene.path, m.line, truncated(r.spec), it->first.line));
      }
    } catch (const InputError& e) {
      throw InputError(scene.path, m.line, e.what());
    }
    if (std::ssize(out) > spectral::kMaxSceneMaterials)
      throw InputError(scene.path, m.line,
                       fmt::format("more than {} materials once page globs are expanded, the "
                                   "most a scene allows (docs/engines.md): split the scene",
                                   spectral::kMaxSceneMaterials));
  }
  return out;
}

}  // namespace

std::vector<LoadedMaterial> load_scene_materials(const Context& ctx, Scene& scene) {
  const auto expanded = expand_scene(ctx, scene);
  std::vector<LoadedMaterial> out;
  const auto& paths = ctx.settings().paths;
  scene.materials.clear();
  for (const auto& [m, page] : expanded) {
    try {
      out.push_back(load_material(ctx, page ? spectral::read_database_page(m.spec, paths)
                                            : spectral::resolve_material(m.spec, paths)));
    } catch (const InputError& e) {
      throw InputError(scene.path, m.line, e.what());
    }
    scene.materials.push_back(m);
  }
  return out;
}

namespace {

// The model's GPU instructions (or texture fetches) summed over the scene's lightings; nullopt if
// one is unmeasured.
std::optional<int> scene_gpu_count(const Scene& scene, const GpuCosts& gpu, Model m,
                                   int GpuCost::*count) {
  int sum = 0;
  for (Lighting l : scene.lightings()) {
    const auto c = gpu.of(m, l);
    if (!c) return std::nullopt;
    sum += (*c).*count;
  }
  return sum;
}
std::optional<int> scene_gpu_instructions(const Scene& scene, const GpuCosts& gpu, Model m) {
  return scene_gpu_count(scene, gpu, m, &GpuCost::instructions);
}

// Orders costs: measured ones by value, then the unmeasured (unknown) ones.
template <class T>
bool cost_less(const std::optional<T>& a, const std::optional<T>& b) {
  if (a.has_value() != b.has_value()) return a.has_value();
  return a && *a < *b;
}
template <class T>
bool cost_differs(const std::optional<T>& a, const std::optional<T>& b) {
  return cost_less(a, b) || cost_less(b, a);
}

}  // namespace

std::vector<PlanChoice> plan_candidates(const Scene& scene,
                                        const std::vector<RenderedCandidate>& rendered,
                                        const std::string& material,
                                        const std::vector<double>& roughness,
                                        const PlanCosts& costs) {
  std::vector<PlanChoice> out;
  for (const auto& r : rendered) {
    PlanChoice c;
    c.material = material;
    c.model = r.model;
    c.set = r.set;
    c.params = r.params;
    c.roughness = roughness;
    c.punctual_rms = r.punctual_rms;
    c.ibl_rms = r.ibl.rms;
    c.area_rms = r.area.rms;
    c.error = -1;
    for (Lighting l : scene.lightings()) {
      if (r.rms_under(l) > c.error) {
        c.error = r.rms_under(l);
        c.error_lighting = l;
      }
    }
    c.gpu_instructions = scene_gpu_instructions(scene, costs.gpu, r.model);
    c.texture_fetches = scene_gpu_count(scene, costs.gpu, r.model, &GpuCost::texture);
    c.ns_per_eval = costs.cpu.ns_per_eval(r.model);
    c.meets_budget = c.error <= scene.max_de00;
    c.f_avg = fresnel::hemispherical_average(r.model, r.params);
    out.push_back(std::move(c));
  }
  return out;
}

PlanChoice choose_model(const std::vector<PlanChoice>& candidates, double max_de00) {
  if (candidates.empty()) throw std::logic_error("no model studied");
  std::vector<PlanChoice> sorted = candidates;
  // stable_sort keeps model_specs() order (derived before fitted) among exact ties.
  std::stable_sort(sorted.begin(), sorted.end(), [](const PlanChoice& a, const PlanChoice& b) {
    if (cost_differs(a.gpu_instructions, b.gpu_instructions))
      return cost_less(a.gpu_instructions, b.gpu_instructions);
    if (cost_differs(a.ns_per_eval, b.ns_per_eval)) return cost_less(a.ns_per_eval, b.ns_per_eval);
    return a.error < b.error;
  });
  for (auto c : sorted)
    if (c.error <= max_de00) {
      c.meets_budget = true;
      return c;
    }
  auto best =
      *std::min_element(candidates.begin(), candidates.end(),
                        [](const PlanChoice& a, const PlanChoice& b) { return a.error < b.error; });
  best.meets_budget = false;
  return best;
}

std::vector<PlanLut> needed_luts(const Scene& scene, const std::vector<Model>& models) {
  std::set<std::string> needed;  // "lighting/channel", from every model's declaration
  for (Model m : models)
    for (Lighting l : scene.lightings())
      for (const char* ch : lighting_support(m, l).channels)
        needed.insert(std::string(lighting_name(l)) + "/" + ch);
  std::vector<PlanLut> out;
  for (const auto& t : lut_textures()) {
    PlanLut lut{t.name, t.lighting, t.file, {}, t.command};
    for (const auto& c : t.channels) {
      if (!needed.count(std::string(t.lighting) + "/" + c.channel)) continue;
      std::string where = c.components;
      std::transform(where.begin(), where.end(), where.begin(),
                     [](unsigned char x) { return std::toupper(x); });
      lut.channels.push_back(where + " " + c.channel);
    }
    if (!lut.channels.empty()) out.push_back(std::move(lut));
  }
  return out;
}

namespace {

// The scene's shader sets, the front, the choice and the tables it reads.
void add_scene_options(Plan& p, const std::vector<MaterialStudy>& studies,
                       const std::vector<std::vector<PlanChoice>>& candidates) {
  std::vector<bool> is_metal;
  std::vector<std::string> groups;
  for (size_t k = 0; k < studies.size(); ++k) {
    is_metal.push_back(studies[k].material->material.material_class ==
                       spectral::MaterialClass::Metal);
    groups.push_back(p.scene.materials.at(k).group);
  }
  p.scene_options =
      scene_options(p.scene, candidates, scene_groupings(is_metal, groups), p.scene.max_de00);
  mark_dominated(p.scene_options);
  p.chosen = choose_scene_option(p.scene_options);
  std::vector<Model> variants;
  for (const auto& g : p.scene_choice().groups) variants.push_back(g.model);
  p.scene_luts = needed_luts(p.scene, variants);
}

}  // namespace

Plan make_plan(const Scene& scene, const Context& ctx, const std::vector<MaterialStudy>& studies,
               const PlanCosts& costs, int lut_size) {
  Plan p;
  p.scene = scene;
  p.space = ctx.settings().space;
  std::map<std::vector<double>, std::vector<ShadingPoint>> points;  // per roughness set
  std::vector<std::vector<PlanChoice>> candidates;
  for (size_t k = 0; k < studies.size(); ++k) {
    const auto& roughness = scene.materials.at(k).roughness;
    auto it = points.find(roughness);
    if (it == points.end()) it = points.emplace(roughness, shading_points(roughness)).first;
    const auto rendered = rendered_candidates(ctx, studies[k], it->second);
    candidates.push_back(
        plan_candidates(scene, rendered, studies[k].material->material.name, roughness, costs));
    p.materials.push_back(choose_model(candidates.back(), scene.max_de00));
  }
  std::vector<Model> chosen;
  for (const auto& m : p.materials) chosen.push_back(m.model);
  p.luts = needed_luts(scene, chosen);
  add_scene_options(p, studies, candidates);
  choose_plan_tables(p, ctx, studies, lut_size);
  for (const auto& spec : fresnel::model_specs())
    if (!scene_gpu_instructions(scene, costs.gpu, spec.model) || !costs.cpu.ns_per_eval(spec.model))
      p.unmeasured.push_back(spec.name);
  return p;
}

std::vector<PlanLut> material_luts(const Plan& plan, size_t k) {
  if (plan.scene.materials.at(k).mirror()) return {};
  return needed_luts(plan.scene, {plan.scene_choice().materials.at(k).model});
}

}  // namespace fl::analysis
