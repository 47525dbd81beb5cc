#pragma once
// The notes and columns every per-material table shares: the colorimetric setting, the
// out-of-range policy and the materials' coverage.
#include <span>
#include <string>
#include <vector>

#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// The colorimetric setting in one sentence, the first note of the tables.
std::string setting_note(const Context& ctx);

// Per-material tables end with the material's coverage (Coverage, docs/conventions.md "Coverage"):
// coverage, coverage_n, coverage_k (empty without k data) and extrapolated (yes / no).
void add_coverage_columns(Table& t);
void add_coverage_cells(std::vector<Cell>& row, const LoadedMaterial& m);
inline constexpr size_t kCoverageColumns = 4;  // the cells add_coverage_cells adds
// The note that explains them, with how many of the table's materials are extrapolated.
std::string coverage_note(const std::vector<const LoadedMaterial*>& materials);
std::vector<const LoadedMaterial*> materials_of(std::span<const MaterialStudy> studies);

}  // namespace fl::analysis
