#include "analysis/study/table_notes.h"

#include <fmt/format.h>

namespace fl::analysis {

std::string setting_note(const Context& ctx) {
  const auto& s = ctx.settings();
  const std::string space = ctx.spaces().is_builtin()
                                ? s.space
                                : fmt::format("{} (OCIO config {}; {})", s.space, s.ocio_config,
                                              ctx.space().white_source);
  return fmt::format(
      "Working space {}, illuminant {}, {} adaptation, CIE 1931 2° observer, {:g}-{:g} nm at {:g} "
      "nm, "
      "{} angles over 0-90°, outside medium η = {:g}.",
      space, s.illuminant, s.adaptation, ctx.grid().start_nm, ctx.grid().end_nm(),
      ctx.grid().step_nm, s.angles, s.eta_outside);
}

void add_coverage_columns(Table& t) {
  for (const char* c : {"coverage", "coverage_n", "coverage_k"}) t.columns.push_back({c, 4});
  t.columns.push_back({"extrapolated"});
}

void add_coverage_cells(std::vector<Cell>& row, const LoadedMaterial& m) {
  const auto& c = m.coverage;
  row.insert(row.end(), {c.both, c.n, c.k, std::string(c.extrapolated ? "yes" : "no")});
}

std::string coverage_note(const std::vector<const LoadedMaterial*>& materials) {
  int held = 0;
  for (const auto* m : materials) held += m->coverage.extrapolated;
  return fmt::format(
      "coverage: the share of 360-830 nm, each wavelength weighted by the illuminant × ȳ, where "
      "the "
      "data measures n and k (coverage_n, coverage_k: each alone; data without k counts k as "
      "given); "
      "extrapolated: somewhere the nearest measured value is held ({} of {} materials).",
      held, materials.size());
}

std::vector<const LoadedMaterial*> materials_of(std::span<const MaterialStudy> studies) {
  std::vector<const LoadedMaterial*> out;
  for (const auto& s : studies) out.push_back(s.material);
  return out;
}

}  // namespace fl::analysis
