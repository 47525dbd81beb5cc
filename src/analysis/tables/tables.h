#pragma once
// The report tables, and the helpers of the one-material commands.
#include <span>

#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// `materials`: the catalog (key, name, class, data source, reference).
Table catalog_table(const spectral::DataPaths& paths);

// The talk's Schlick table: ΔE2000 of Schlick (F0 from the spectral procedure) against spectral
// ground truth, per catalog material.
Table schlick_table(const Context& ctx, const std::vector<LoadedMaterial>& materials);

// The talk's table of derivation methods, metals only.
Table methods_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

// Every material × every model × {derived, fitted}: RMS, mean, max and render-weighted RMS.
Table models_table(const Context& ctx, std::span<const MaterialStudy> studies);

// `curve`: per material and angle, ground truth, model and ΔE2000, then the material, its
// coverage and the fit's flags (fit::fit_flags; empty for derived parameters). `parameters` is
// "derived" or "fitted".
Table curve_table(const Context& ctx, const std::vector<LoadedMaterial>& materials,
                  const std::string& model, const std::string& parameters = "derived");

}  // namespace fl::analysis
