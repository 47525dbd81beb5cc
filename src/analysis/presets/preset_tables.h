#pragma once
// The presets tables: shading-model parameters per material, and OpenPBR Surface's.
#include <string>
#include <vector>

#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// A page's kind and its detail ("thin film 25 nm"), "consensus" for a consensus material, empty for
// other materials.
std::string page_kind_text(const spectral::Material& m);

// F0, F82, g, η, κ per material (values outside [0, 1] kept and flagged in out_of_range,
// analysis/presets/shading_presets.h), and the coefficients of the basis model with
// `basis_terms` terms (basis3, basis4 or basis5).
inline constexpr int kPresetBasisTerms = 4;
Table presets_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                    int basis_terms = kPresetBasisTerms);
// OpenPBR Surface parameters per material (open_pbr_parameters).
Table openpbr_table(const Context& ctx, const std::vector<MaterialStudy>& studies);
// The studies the presets tables read: the RGB η, κ fit only (presets_table), no fit
// (openpbr_table).
StudyOptions presets_study_options(bool openpbr);

}  // namespace fl::analysis
