// The size and storage of the tables a plan's chosen option reads (make_plan).
#include <algorithm>
#include <map>

#include "analysis/plan/plan.h"

namespace fl::analysis {

namespace {

struct TableConfig {
  int size;
  TexelStorage storage;
  long bytes;
};

// Every size (or the forced one) in half and float, fewest bytes first (ties: half first). Under
// area lights no size below kEngineLutSize: the LTC matrix (ltc_1), the lobe's shape, is fitted
// per texel, and its accuracy is not part of the rendered error the budget weighs.
std::vector<TableConfig> table_configs(const Plan& p, int lut_size) {
  std::vector<TableConfig> out;
  for (int size : kPlanLutSizes) {
    if (lut_size != 0 && size != lut_size) continue;
    if (lut_size == 0 && p.scene.area && size < kEngineLutSize) continue;
    for (const auto storage : {TexelStorage::Half, TexelStorage::Float}) {
      long bytes = 0;
      for (const auto& l : p.scene_luts) bytes += lut_texture_bytes(l.name, size, storage);
      out.push_back({size, storage, bytes});
    }
  }
  if (out.empty())  // a forced size outside kPlanLutSizes
    for (const auto storage : {TexelStorage::Half, TexelStorage::Float}) {
      long bytes = 0;
      for (const auto& l : p.scene_luts) bytes += lut_texture_bytes(l.name, lut_size, storage);
      out.push_back({lut_size, storage, bytes});
    }
  std::stable_sort(out.begin(), out.end(),
                   [](const TableConfig& a, const TableConfig& b) { return a.bytes < b.bytes; });
  return out;
}

// Each material's error as rendered (its largest over the scene's lightings) when the engine reads
// `tables`; truth[k] at material k's points.
std::vector<double> errors_with(const Plan& p, const Context& ctx,
                                const std::vector<std::vector<color::Rgb>>& truth,
                                const EngineTables& tables) {
  std::map<std::vector<double>, std::vector<ShadingPoint>> points;
  const auto& option = p.scene_choice();
  std::vector<double> out;
  for (size_t k = 0; k < option.materials.size(); ++k) {
    const auto& m = option.materials[k];
    double e = m.punctual_rms * p.scene.punctual;
    const auto& roughness = p.scene.materials.at(k).roughness;
    auto it = points.find(roughness);
    if (it == points.end())
      it = points.emplace(roughness, shading_points(roughness, 0, tables)).first;
    for (const Lighting l : p.scene.lightings())
      if (l != Lighting::Punctual)
        e = std::max(
            e, error_stats(rendered_de00(ctx, truth[k], m.model, m.params, l, it->second)).rms);
    out.push_back(e);
  }
  return out;
}

}  // namespace

void choose_plan_tables(Plan& p, const Context& ctx, const std::vector<MaterialStudy>& studies,
                        int lut_size) {
  p.tables = PlanTables{};
  p.tables.forced = lut_size != 0;
  if (p.scene_luts.empty()) return;
  const auto& option = p.scene_choice();
  std::vector<std::vector<color::Rgb>> truth;
  std::vector<double> reference;  // each material's error with the 64² float tables
  const auto at_reference = engine_tables();
  for (size_t k = 0; k < option.materials.size(); ++k)
    truth.push_back(lobe_truth(ctx, *studies.at(k).material,
                               shading_points(p.scene.materials.at(k).roughness, 0, at_reference)));
  reference = errors_with(p, ctx, truth, at_reference);
  bool found = false;
  for (const auto& c : table_configs(p, lut_size)) {
    const auto errors = errors_with(p, ctx, truth, engine_tables(c.size, c.storage));
    bool ok = true;
    for (size_t k = 0; k < errors.size(); ++k)
      ok = ok && errors[k] <= std::max(p.scene.max_de00, reference[k]);
    const double worst = *std::max_element(errors.begin(), errors.end());
    if (ok || (!found && (p.tables.bytes == 0 || worst < p.tables.worst_de00))) {
      p.tables.size = c.size;
      p.tables.storage = c.storage;
      p.tables.bytes = c.bytes;
      p.tables.worst_de00 = worst;
    }
    if (ok) {
      found = true;
      break;
    }
  }
}

}  // namespace fl::analysis
