// The scene's shader sets (analysis/plan/plan.h): groupings, options, their costs, the Pareto front
// and the choice.
#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/lut/lut_layout.h"
#include "analysis/plan/plan.h"
#include "fresnel/registered_models.h"
#include "util/quantile.h"

namespace fl::analysis {

using fresnel::Model;

namespace {

// Measured before unmeasured; measured by value.
int compare_optional(const std::optional<int>& a, const std::optional<int>& b) {
  if (a.has_value() != b.has_value()) return a.has_value() ? -1 : 1;
  if (!a) return 0;
  return *a < *b ? -1 : *a > *b ? 1 : 0;
}

int compare_cost(const SceneCost& a, const SceneCost& b) {
  if (int c = compare_optional(a.gpu_instructions, b.gpu_instructions)) return c;
  if (int c = compare_optional(a.texture_fetches, b.texture_fetches)) return c;
  if (a.table_bytes != b.table_bytes) return a.table_bytes < b.table_bytes ? -1 : 1;
  if (a.variants != b.variants) return a.variants < b.variants ? -1 : 1;
  return 0;
}

}  // namespace

bool scene_cost_less(const SceneCost& a, const SceneCost& b) {
  return compare_cost(a, b) < 0;
}

long lut_texture_bytes(const std::string& texture, int size, TexelStorage storage) {
  for (const auto& t : lut_textures()) {
    if (texture != t.name) continue;
    long components = 0;
    for (const auto& c : t.channels) components += static_cast<long>(std::strlen(c.components));
    return static_cast<long>(size) * size * components * (storage == TexelStorage::Float ? 4 : 2);
  }
  throw std::logic_error("no lookup table texture " + texture);
}

std::vector<Grouping> scene_groupings(const std::vector<bool>& is_metal,
                                      const std::vector<std::string>& scene_group) {
  const size_t n = is_metal.size();
  std::vector<Grouping> out;
  Grouping all{"one shader", {"all"}, {{}}};
  for (size_t k = 0; k < n; ++k) all.groups[0].push_back(k);
  out.push_back(all);
  Grouping by_class{"by class", {"metal", "dielectric"}, {{}, {}}};
  for (size_t k = 0; k < n; ++k) by_class.groups[is_metal[k] ? 0 : 1].push_back(k);
  if (!by_class.groups[0].empty() && !by_class.groups[1].empty()) out.push_back(by_class);
  std::map<std::string, size_t> index;  // group name → position, in order of first appearance
  Grouping named{"by scene group", {}, {}};
  bool any_named = false;
  for (size_t k = 0; k < n; ++k) {
    const std::string name = scene_group.at(k).empty() ? "other" : scene_group[k];
    any_named = any_named || !scene_group[k].empty();
    auto it = index.find(name);
    if (it == index.end()) {
      it = index.emplace(name, named.names.size()).first;
      named.names.push_back(name);
      named.groups.emplace_back();
    }
    named.groups[it->second].push_back(k);
  }
  const bool repeats = std::any_of(out.begin(), out.end(), [&](const Grouping& g) {
    return std::set(g.groups.begin(), g.groups.end()) ==
           std::set(named.groups.begin(), named.groups.end());
  });
  if (any_named && named.groups.size() > 1 && !repeats) out.push_back(named);
  return out;
}

namespace {

// A model's candidate of lowest error for one material (the first listed on a tie).
const PlanChoice& best_of(const std::vector<PlanChoice>& per_material, Model m) {
  const PlanChoice* best = nullptr;
  for (const auto& c : per_material)
    if (c.model == m && (!best || c.error < best->error)) best = &c;
  if (!best) throw std::logic_error("a material without a candidate of a model");
  return *best;
}

// What one model costs and errs over one group of materials.
struct GroupModel {
  Model model{};
  std::optional<int> instructions, fetches;
  std::set<std::string> textures;
  double worst = 0;
};

std::set<std::string> textures_of(const Scene& scene, const std::vector<Model>& models) {
  std::set<std::string> out;
  for (const auto& l : needed_luts(scene, models)) out.insert(l.name);
  return out;
}

GroupModel group_model(const Scene& scene, const std::vector<std::vector<PlanChoice>>& candidates,
                       const std::vector<size_t>& group, Model m) {
  GroupModel g{m, {}, {}, textures_of(scene, {m}), 0.0};
  for (size_t k : group) {
    const auto& c = best_of(candidates.at(k), m);
    g.instructions = c.gpu_instructions;
    g.fetches = c.texture_fetches;
    g.worst = std::max(g.worst, c.error);
  }
  return g;
}

// b can replace a in any option at no more cost and no more worst error.
bool replaces(const GroupModel& b, const GroupModel& a) {
  return compare_optional(b.instructions, a.instructions) <= 0 &&
         compare_optional(b.fetches, a.fetches) <= 0 &&
         std::includes(a.textures.begin(), a.textures.end(), b.textures.begin(),
                       b.textures.end()) &&
         b.worst <= a.worst;
}

// The models a group keeps: those no other replaces (of two that replace each other, the first).
std::vector<GroupModel> kept_models(const std::vector<GroupModel>& all) {
  std::vector<GroupModel> out;
  for (size_t i = 0; i < all.size(); ++i) {
    bool dropped = false;
    for (size_t j = 0; j < all.size() && !dropped; ++j)
      dropped = j != i && replaces(all[j], all[i]) && (j < i || !replaces(all[i], all[j]));
    if (!dropped) out.push_back(all[i]);
  }
  return out;
}

// The largest of the variants' counts; unmeasured if one is.
std::optional<int> dearest(const std::vector<std::optional<int>>& counts) {
  std::optional<int> out = 0;
  for (const auto& c : counts) {
    if (!c) return std::nullopt;
    out = std::max(*out, *c);
  }
  return out;
}

SceneCost option_cost(const Scene& scene, const std::vector<std::vector<PlanChoice>>& candidates,
                      const SceneOption& o) {
  std::vector<Model> variants;
  std::vector<std::optional<int>> instructions, fetches;
  for (const auto& g : o.groups) {
    if (std::find(variants.begin(), variants.end(), g.model) != variants.end()) continue;
    variants.push_back(g.model);
    const auto& c = best_of(candidates.at(g.materials.front()), g.model);
    instructions.push_back(c.gpu_instructions);
    fetches.push_back(c.texture_fetches);
  }
  SceneCost cost{dearest(instructions), dearest(fetches), 0, static_cast<int>(variants.size())};
  for (const auto& t : textures_of(scene, variants)) cost.table_bytes += lut_texture_bytes(t);
  return cost;
}

SceneOption make_option(const Scene& scene, const std::vector<std::vector<PlanChoice>>& candidates,
                        const Grouping& grouping, const std::vector<Model>& models,
                        double max_de00) {
  SceneOption o;
  o.grouping = grouping.name;
  o.materials.resize(candidates.size());
  for (size_t i = 0; i < grouping.groups.size(); ++i) {
    o.groups.push_back({grouping.names[i], models[i], grouping.groups[i]});
    const std::string model_name = fresnel::model_spec(models[i]).name;
    o.name += grouping.groups.size() == 1
                  ? model_name
                  : (o.name.empty() ? "" : ", ") + grouping.names[i] + ": " + model_name;
    for (size_t k : grouping.groups[i]) {
      PlanChoice c = best_of(candidates.at(k), models[i]);
      c.meets_budget = c.error <= max_de00;
      o.materials[k] = std::move(c);
    }
  }
  std::vector<double> errors;
  for (const auto& c : o.materials) {
    errors.push_back(c.error);
    o.worst_de00 = std::max(o.worst_de00, c.error);
    if (!c.meets_budget) o.failing.push_back(c.material);
  }
  o.median_de00 = median(errors);
  o.cost = option_cost(scene, candidates, o);
  return o;
}

// At most kMaxSplitOptions combinations: while there are more, the longest list drops its model
// of most instructions (an unmeasured one first). Scenes with a handful of groups never reach it.
constexpr size_t kMaxSplitOptions = 4096;
void limit_combinations(std::vector<std::vector<GroupModel>>& kept) {
  const auto count = [&] {
    size_t n = 1;
    for (const auto& k : kept) n = std::min(n * k.size(), kMaxSplitOptions + 1);
    return n;
  };
  while (count() > kMaxSplitOptions) {
    auto& longest = *std::max_element(
        kept.begin(), kept.end(), [](const auto& a, const auto& b) { return a.size() < b.size(); });
    longest.erase(
        std::max_element(longest.begin(), longest.end(), [](const auto& a, const auto& b) {
          return compare_optional(a.instructions, b.instructions) < 0;
        }));
  }
}

// Every combination of the groups' kept models but those giving all groups one model.
void add_splits(const Scene& scene, const std::vector<std::vector<PlanChoice>>& candidates,
                const Grouping& grouping, double max_de00, std::vector<SceneOption>& out) {
  std::vector<std::vector<GroupModel>> kept;
  for (const auto& group : grouping.groups) {
    std::vector<GroupModel> all;
    for (const auto& spec : fresnel::model_specs())
      all.push_back(group_model(scene, candidates, group, spec.model));
    kept.push_back(kept_models(all));
  }
  limit_combinations(kept);
  std::vector<size_t> at(kept.size(), 0);  // an odometer over the kept lists
  for (;;) {
    std::vector<Model> models;
    for (size_t i = 0; i < kept.size(); ++i) models.push_back(kept[i][at[i]].model);
    const bool one_model =
        std::all_of(models.begin(), models.end(), [&](Model m) { return m == models.front(); });
    if (!one_model) out.push_back(make_option(scene, candidates, grouping, models, max_de00));
    size_t i = 0;
    while (i < at.size() && ++at[i] == kept[i].size()) at[i++] = 0;
    if (i == at.size()) return;
  }
}

bool dominates(const SceneOption& a, const SceneOption& b) {
  const int c = compare_cost(a.cost, b.cost);
  return c <= 0 && a.worst_de00 <= b.worst_de00 && (c < 0 || a.worst_de00 < b.worst_de00);
}

}  // namespace

std::vector<SceneOption> scene_options(const Scene& scene,
                                       const std::vector<std::vector<PlanChoice>>& candidates,
                                       const std::vector<Grouping>& groupings, double max_de00) {
  if (candidates.empty()) throw std::logic_error("a scene without materials");
  std::vector<SceneOption> out;
  for (const auto& g : groupings) {
    if (g.groups.size() > 1) {
      add_splits(scene, candidates, g, max_de00, out);
      continue;
    }
    for (const auto& spec : fresnel::model_specs())
      out.push_back(make_option(scene, candidates, g, {spec.model}, max_de00));
  }
  return out;
}

void mark_dominated(std::vector<SceneOption>& options) {
  std::vector<bool> on_front(options.size(), true);
  for (size_t i = 0; i < options.size(); ++i)
    for (size_t j = 0; j < options.size() && on_front[i]; ++j)
      on_front[i] = !dominates(options[j], options[i]);
  for (size_t i = 0; i < options.size(); ++i) {
    options[i].dominated_by.reset();
    if (on_front[i]) continue;
    // The cheapest option of the front dominating it (then the more accurate).
    for (size_t j = 0; j < options.size(); ++j) {
      if (!on_front[j] || !dominates(options[j], options[i])) continue;
      const auto& best = options[i].dominated_by;
      const int c = best ? compare_cost(options[j].cost, options[*best].cost) : -1;
      if (c < 0 || (c == 0 && options[j].worst_de00 < options[*best].worst_de00))
        options[i].dominated_by = j;
    }
  }
}

size_t choose_scene_option(const std::vector<SceneOption>& options) {
  if (options.empty()) throw std::logic_error("no scene option");
  auto better = [](const SceneOption& a, const SceneOption& b) {
    if (a.meets_every_budget() != b.meets_every_budget()) return a.meets_every_budget();
    if (!a.meets_every_budget() && a.worst_de00 != b.worst_de00) return a.worst_de00 < b.worst_de00;
    if (const int c = compare_cost(a.cost, b.cost)) return c < 0;
    return a.worst_de00 < b.worst_de00;
  };
  return static_cast<size_t>(std::min_element(options.begin(), options.end(), better) -
                             options.begin());
}

}  // namespace fl::analysis
