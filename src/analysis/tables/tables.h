#pragma once
// The report tables, and the helpers of the one-material commands.
#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"
#include "analysis/tables/table.h"

namespace fl::analysis {

// The colorimetric setting in one sentence, the first note of the tables.
std::string setting_note(const Context& ctx);
// The out-of-range policy in one sentence, with the number of materials flagged.
std::string out_of_range_note(int flagged);

// Per-material tables end with the material's coverage (Coverage, docs/conventions.md "Coverage"):
// coverage, coverage_n, coverage_k (empty without k data) and extrapolated (yes / no).
void add_coverage_columns(Table& t);
void add_coverage_cells(std::vector<Cell>& row, const LoadedMaterial& m);
// The note that explains them, with how many of the table's materials are extrapolated.
std::string coverage_note(const std::vector<const LoadedMaterial*>& materials);
std::vector<const LoadedMaterial*> materials_of(const std::vector<MaterialStudy>& studies);

// `materials`: the catalog (key, name, class, data source, reference).
Table catalog_table(const spectral::DataPaths& paths);

// The talk's Schlick table: ΔE2000 of Schlick (F0 from the spectral procedure) against spectral
// ground truth, per catalog material.
Table schlick_table(const Context& ctx, const std::vector<LoadedMaterial>& materials);

// The talk's table of derivation methods, metals only.
Table methods_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

// Every material × every model × {derived, fitted}: RMS, mean, max and render-weighted RMS.
Table models_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

// A page's kind and its detail ("thin film 25 nm"), "consensus" for a consensus material, empty for
// other materials.
std::string page_kind_text(const spectral::Material& m);

// F0, F82, g, η, κ per material (values outside [0, 1] kept and flagged in out_of_range,
// analysis/tables/shading_presets.h), and the coefficients of the basis model with
// `basis_terms` terms (basis3, basis4 or basis5).
inline constexpr int kPresetBasisTerms = 4;
Table presets_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                    int basis_terms = kPresetBasisTerms);
// OpenPBR Surface parameters per material (open_pbr_parameters).
Table openpbr_table(const Context& ctx, const std::vector<MaterialStudy>& studies);
// The studies the presets tables read: the RGB η, κ fit only (presets_table), no fit
// (openpbr_table).
StudyOptions presets_study_options(bool openpbr);

// "schlick, generalized_schlick, ...": every model's name, for option help.
std::string model_names();

// The study of one material with the parameter set `kind` names (parameter_set_from_name): curve
// fits for "fitted" and "rendered", and then only of `models` (empty: every model); rendered fits
// (add_rendered_fits at lut_accuracy_points) for "rendered". `one` holds the material and must
// outlive the study, which points into it.
MaterialStudy study_one(const Context& ctx, const std::vector<LoadedMaterial>& one,
                        const std::string& kind, const std::vector<fresnel::Model>& models = {});
// A model's derived, fitted or rendered parameters (`kind`) from a study.
const std::vector<double>& model_params(const MaterialStudy& st, fresnel::Model m,
                                        const std::string& kind);

// `curve`: per material and angle, ground truth, model and ΔE2000, then the material, its
// coverage and the fit's flags (fit::fit_flags; empty for derived parameters). `parameters` is
// "derived" or "fitted".
Table curve_table(const Context& ctx, const std::vector<LoadedMaterial>& materials,
                  const std::string& model, const std::string& parameters = "derived");

}  // namespace fl::analysis
