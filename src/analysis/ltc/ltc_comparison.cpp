#include "analysis/ltc/ltc_comparison.h"

#include <fmt/format.h>

namespace fl::analysis {

std::vector<Table> ltc_comparison_tables(const LtcComparison& c) {
  Table bands;
  bands.name = "ltc-bands";
  bands.title = "Held-out relative L3 error per band";
  bands.columns = {{"band"},   {"cells", 0},       {"mean", 4}, {"ltc_code_mean", 4},
                   {"max", 4}, {"ltc_code_max", 4}};
  for (const auto& b : c.bands)
    bands.rows.push_back({b.band, static_cast<long long>(b.cells), b.mean, b.reference_mean, b.max,
                          b.reference_max});
  Table jumps;
  jumps.name = "ltc-jumps";
  jumps.title = "Largest difference of a texture entry between neighbouring cells";
  jumps.columns = {
      {"entry"}, {"max", 4}, {"at (i_nov, j_roughness)"}, {"ltc_code_max", 4}, {"ltc_code at"}};
  auto where = [](int i, int j, bool along_nov) {
    return fmt::format("({}, {}) to ({}, {})", i, j, i + (along_nov ? 1 : 0),
                       j + (along_nov ? 0 : 1));
  };
  std::string above;
  for (const auto& j : c.jumps) {
    jumps.rows.push_back(
        {j.entry, j.max, where(j.i_nov, j.j_roughness, j.along_nov), j.reference_max,
         where(j.reference_i_nov, j.reference_j_roughness, j.reference_along_nov)});
    if (j.max > j.reference_max)
      above += fmt::format("{}{} ({:.4f} against {:.4f})", above.empty() ? "" : ", ", j.entry,
                           j.max, j.reference_max);
  }
  jumps.reading =
      above.empty() ? "No entry steps further between neighbouring cells than in ltc_code's table."
                    : "Entries whose largest step exceeds ltc_code's largest: " + above + ".";
  Table mid;
  mid.name = "ltc-midpoints";
  mid.title = "Held-out relative L3 error of bilinear lookups half-way between neighbouring cells";
  mid.columns = bands.columns;
  mid.columns[1].name = "midpoints";
  for (const auto& b : c.midpoint_bands)
    mid.rows.push_back({b.band, static_cast<long long>(b.cells), b.mean, b.reference_mean, b.max,
                        b.reference_max});
  mid.reading = fmt::format(
      "Largest excess of a midpoint's error over the larger error of its two cells (a step between "
      "cells shows "
      "here): {:.4f}, ltc_code {:.4f}.",
      c.midpoint_excess, c.midpoint_reference_excess);
  return {bands, jumps, mid};
}

}  // namespace fl::analysis
