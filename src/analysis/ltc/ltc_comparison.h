#pragma once
// A fitted LTC table against ltc_code's published fit (analysis/ltc/ltc_reference.h) as report
// tables.
#include <vector>

#include "analysis/ltc/ltc_reference.h"
#include "util/table.h"

namespace fl::analysis {

// The comparison as tables for Markdown: held-out errors per band, neighbour jumps of the texture
// entries, and the errors of bilinear lookups half-way between cells per band.
std::vector<Table> ltc_comparison_tables(const LtcComparison& c);

}  // namespace fl::analysis
