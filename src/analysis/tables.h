#pragma once
// The report tables (SPEC §6).
#include "analysis/context.h"
#include "analysis/table.h"

namespace fl::analysis {

// The talk's Schlick table: ΔE2000 of Schlick (F0 from the spectral procedure) against spectral
// ground truth, per catalog material.
Table schlick_table(const Context& ctx, const std::vector<LoadedMaterial>& materials);

// One curve's worth of output for `curve`: per angle, ground truth, model and ΔE2000.
Table curve_table(const Context& ctx, const LoadedMaterial& m, const std::string& model);

}  // namespace fl::analysis
