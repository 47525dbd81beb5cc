#pragma once
// A fitted LTC table against ltc_code's published GGX fit (Heitz, Dupuy, Hill & Neubelt 2016,
// "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines"; the table is
// fit/results/ltc.inc of Heitz & Hill's ltc_code), cell by cell on one held-out error.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "analysis/ltc/ltc_table.h"

namespace fl::analysis {

// ltc_code's ltc.inc: `size`² cells of tabMinv (glm mat3, column-major) and tabMagnitude, cell a +
// size·t for roughness a/(size − 1) and view x = t/(size − 1) = √(1 − cos θ), the axes of
// ltc_grid(size). Stored here in LutGrid order (cell(i_nov = t, j_roughness = a)), M⁻¹ row-major.
struct LtcReferenceTable {
  int size = 0;
  std::vector<LtcMatrix> m_inv;
  std::vector<double> magnitude;
};
// Throws InputError naming the file (and line) when it is missing or not of that form.
LtcReferenceTable read_ltc_code_table(const std::string& path);

// Per cell the held-out relative L3 error ltc_l3_error of both tables, each LTC scaled by the
// fitted table's n_D (the magnitude is not part of either fit), with `heldout_samples` directions
// per strategy; per band the mean and max; per texture entry (LtcCell::inv_packed) the largest
// difference between neighbouring cells; and the same error half-way between neighbouring cells (in
// texture coordinates) for the LTC a bilinear lookup gives there, the mean of the two cells'
// entries, against the lobe at that n·v and α (n_D from integrate_moments with `moment_samples`).
struct LtcBandError {
  std::string band;
  int cells = 0;
  double mean = 0, max = 0, reference_mean = 0, reference_max = 0;
};
struct LtcEntryJump {
  std::string entry;
  double max = 0, reference_max = 0;
  int i_nov = 0, j_roughness = 0, reference_i_nov = 0,
      reference_j_roughness = 0;  // where, and towards i + 1 or j + 1
  bool along_nov = false, reference_along_nov = false;
};
struct LtcComparison {
  int heldout_samples = 0;
  std::vector<double> error, reference_error;  // per cell, LutGrid order
  std::vector<LtcBandError> bands;
  std::array<LtcEntryJump, 4> jumps;
  std::vector<std::pair<int, int>> midpoint_cells;  // the two cells of each midpoint
  std::vector<double> midpoint_error, midpoint_reference_error;
  std::vector<LtcBandError> midpoint_bands;
  // The largest excess of a midpoint's error over the larger error of its two cells.
  double midpoint_excess = 0, midpoint_reference_excess = 0;
};
LtcComparison compare_ltc_tables(const LtcTable& table, const LtcReferenceTable& reference,
                                 int heldout_samples, int moment_samples = kLutSamples);
// The jumps of LtcComparison alone: per texture entry the largest difference between neighbouring
// cells of each table.
std::array<LtcEntryJump, 4> ltc_entry_jumps(const LtcTable& table,
                                            const LtcReferenceTable& reference);

}  // namespace fl::analysis
