#include "analysis/tables/tables.h"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/lut/lut_accuracy.h"
#include "analysis/presets/shading_presets.h"
#include "analysis/study/table_notes.h"
#include "fresnel/average.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "util/errors.h"
#include "util/quantile.h"

namespace fl::analysis {

Table schlick_table(const Context& ctx, const std::vector<LoadedMaterial>& materials) {
  Table t;
  t.name = "schlick";
  t.title = "Schlick against spectral ground truth (ΔE2000)";
  t.columns = {{"material"},    {"class"},        {"source"},
               {"rms_de00", 3}, {"mean_de00", 3}, {"max_de00", 3}};
  add_coverage_columns(t);
  std::vector<const LoadedMaterial*> all;
  for (const auto& m : materials) {
    const auto truth = ground_truth_curve(ctx, m.ior, ctx.settings().eta_outside);
    const auto e = curve_error(ctx, truth, schlick_curve(ctx, truth.front()));
    t.rows.push_back({m.material.name, std::string(spectral::to_string(m.material.material_class)),
                      m.material.source, e.rms, e.mean, e.max});
    add_coverage_cells(t.rows.back(), m);
    all.push_back(&m);
  }
  t.reading =
      "Schlick's model with F0 taken from the spectral ground truth at normal incidence, per "
      "material. "
      "Metals with a strongly coloured grazing tint (chromium, zinc, iron) are where Schlick is "
      "weakest.";
  t.notes = {setting_note(ctx),
             "ΔE2000 per Sharma, Wu & Dalal 2005; RMS, mean and max over the incidence angles.",
             coverage_note(all)};
  return t;
}

namespace {

// One material's rows of the curve table.
void add_curve_rows(Table& t, const Context& ctx, const LoadedMaterial& m,
                    const fresnel::ModelSpec& spec, const std::string& parameters) {
  const std::vector<LoadedMaterial> one{m};
  const auto st = study_one(ctx, one, parameters, {spec.model});
  const auto& params = model_params(st, spec.model, parameters);
  const auto approx = fresnel::evaluate_curve(spec.model, params, ctx.cos_thetas());
  const auto de = de2000_per_angle(ctx, st.truth, approx);
  const ParameterSet set = parameter_set_from_name(parameters);
  const auto& r = st.result(spec.model);
  const std::string flags = set == ParameterSet::Fitted     ? fit::fit_flags(r.fitted)
                            : set == ParameterSet::Rendered ? fit::fit_flags(r.rendered)
                                                            : "";
  for (size_t i = 0; i < st.truth.size(); ++i) {
    t.rows.push_back({ctx.angles_deg()[i], st.truth[i].r, st.truth[i].g, st.truth[i].b, approx[i].r,
                      approx[i].g, approx[i].b, de[i], m.material.name});
    add_coverage_cells(t.rows.back(), m);
    t.rows.back().push_back(flags);
  }
  const auto names = spec.param_names();
  std::string p;
  for (size_t i = 0; i < names.size(); ++i)
    p += fmt::format("{}{}={:.6f}", i ? ", " : "", names[i], params[i]);
  t.notes.push_back(fmt::format("{} parameters: {}{}", m.material.name, p,
                                flags.empty() ? "" : " (fit: " + flags + ")"));
  if (m.coverage.extrapolated)
    t.notes.push_back(fmt::format("{}: extrapolated, {}", m.material.name, m.coverage.uncovered));
}

}  // namespace

Table curve_table(const Context& ctx, const std::vector<LoadedMaterial>& materials,
                  const std::string& model, const std::string& parameters) {
  const auto& spec = fresnel::model_from_name(model);
  parameter_set_from_name(parameters);
  Table t;
  t.name = "curve";
  t.title = materials.size() == 1
                ? fmt::format("{}: ground truth and {} ({} parameters) per angle",
                              materials.front().material.name, spec.label, parameters)
                : fmt::format("Ground truth and {} ({} parameters) per angle, {} materials",
                              spec.label, parameters, materials.size());
  t.columns = {{"theta_deg", 2}, {"truth_r", 6}, {"truth_g", 6}, {"truth_b", 6}, {"model_r", 6},
               {"model_g", 6},   {"model_b", 6}, {"de00", 4},    {"material"}};
  add_coverage_columns(t);
  t.columns.push_back({"fit_flags"});
  t.notes = {setting_note(ctx)};
  for (const auto& m : materials) add_curve_rows(t, ctx, m, spec, parameters);
  std::vector<const LoadedMaterial*> all;
  for (const auto& m : materials) all.push_back(&m);
  t.notes.push_back(coverage_note(all));
  return t;
}

namespace {

std::string params_text(fresnel::Model m, const std::vector<double>& p) {
  const auto names = fresnel::model_spec(m).param_names();
  std::string out;
  for (size_t i = 0; i < p.size(); ++i)
    out += fmt::format("{}{}={:.5f}", i ? " " : "", names[i], p[i]);
  return out;
}

std::string fit_flags_note(std::span<const MaterialStudy> studies) {
  int flagged = 0, fits = 0;
  for (const auto& s : studies)
    for (const auto& r : s.models) {
      ++fits;
      flagged += !fit::fit_flags(r.fitted).empty();
    }
  return fmt::format(
      "fit_flags ({} of {} fits): at_bound:NAME a parameter ended on its fit box where the model "
      "goes "
      "on; iteration_limit the solver stopped at its iteration limit; kept_start no solve improved "
      "on "
      "the best start, which is published instead (a fit never publishes worse than its best "
      "start). "
      "Lossless materials (k ≤ {:g} everywhere) keep κ = 0 in their fits.",
      flagged, fits, fit::kLosslessMaxK);
}

}  // namespace

Table methods_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  using fresnel::Model;
  Table t;
  t.name = "methods";
  t.title = "Ways to derive RGB parameters from spectral data (RMS ΔE2000, metals)";
  t.columns = {{"material"},           {"schlick", 3},        {"ps_eta_kappa", 3},
               {"refl_eta_kappa", 3},  {"refl_f0_ps_eta", 3}, {"refl_f0_refl_eta", 3},
               {"fitted_eta_kappa", 3}};
  add_coverage_columns(t);
  int g_clamped_ps = 0, g_clamped_refl = 0;
  std::vector<const LoadedMaterial*> metals;
  for (const auto& s : studies) {
    if (!s.is_metal()) continue;
    t.rows.push_back({s.material->material.name,
                      s.result(fresnel::model_of<fresnel::models::Schlick>).derived_error.rms,
                      s.ps_eta_kappa.rms,
                      s.result(fresnel::model_of<fresnel::models::FresnelRgb>).derived_error.rms,
                      s.refl_f0_ps_eta.rms,
                      s.result(fresnel::model_of<fresnel::models::Gulbrandsen>).derived_error.rms,
                      s.result(fresnel::model_of<fresnel::models::FresnelRgb>).fitted_error.rms});
    add_coverage_cells(t.rows.back(), *s.material);
    metals.push_back(s.material);
    g_clamped_ps += s.g_clamped_ps;
    g_clamped_refl += s.g_clamped_refl;
  }
  const auto& ps = fresnel::kDefaultPointSampleNm;
  t.reading =
      "Deriving Gulbrandsen's (F0, g) from the spectral F0 and the reflectance-processed η is "
      "nearly as good as "
      "fitting RGB η, κ numerically; point-sampled η, κ are much worse, and processing η, κ as "
      "reflectances and "
      "using them directly in the Fresnel equations is worst for coloured metals.";
  t.notes = {
      setting_note(ctx),
      fmt::format(
          "PS: η, κ point-sampled at {:g}, {:g}, {:g} nm (R, G, B): the monochromatic primaries of "
          "Rec.2020, the nearest thing an RGB space has to one wavelength per channel.",
          ps[0], ps[1], ps[2]),
      "Refl.: η(λ), κ(λ) pushed through the reflectance → RGB procedure as if they were "
      "reflectances.",
      "Gulbrandsen columns: g from (F0, η) by inverting η(r, g), clamped to [0, 1]; channels "
      "clamped: " +
          fmt::format("{} (PS η), {} (Refl. η).", g_clamped_ps, g_clamped_refl),
      "Fitted: RGB η, κ fitted with Ceres (Levenberg-Marquardt, bounded) to minimize the RMS "
      "ΔE2000 over angles, "
      "started from the Refl. η, κ, Gulbrandsen and PS values; the best start wins.",
      coverage_note(metals)};
  return t;
}

namespace {

// One model's derived (fitted = 0) or fitted row of the models table.
std::vector<Cell> models_row(const MaterialStudy& s, const ModelResult& r, int fitted) {
  const auto& spec = fresnel::model_spec(r.model);
  const auto& e = fitted ? r.fitted_error : r.derived_error;
  const bool clamps = fitted ? r.fitted_clamps : r.derived_clamps;
  std::vector<Cell> row{s.material->material.name,
                        std::string(spectral::to_string(s.material->material.material_class)),
                        std::string(spec.name),
                        std::string(fitted ? "fitted" : "derived"),
                        e.rms,
                        e.mean,
                        e.max,
                        e.rms_weighted,
                        std::string(clamps ? "yes" : "no"),
                        fitted ? static_cast<long long>(r.fitted.iterations) : 0LL,
                        std::string(fitted ? r.fitted.termination : "-"),
                        params_text(r.model, fitted ? r.fitted.parameters : r.derived)};
  row.reserve(row.size() + kCoverageColumns + 1);
  add_coverage_cells(row, *s.material);
  row.push_back(fitted ? fit::fit_flags(r.fitted) : std::string());
  return row;
}

}  // namespace

Table models_table(const Context& ctx, std::span<const MaterialStudy> studies) {
  Table t;
  t.name = "models";
  t.title = "Every Fresnel model, derived and fitted parameters (ΔE2000)";
  t.columns = {{"material"},        {"class"},
               {"model"},           {"parameters"},
               {"rms_de00", 3},     {"mean_de00", 3},
               {"max_de00", 3},     {"rms_weighted_de00", 3},
               {"clamped"},         {"fit_iterations", 0},
               {"fit_termination"}, {"values"}};
  add_coverage_columns(t);
  t.columns.push_back({"fit_flags"});
  std::vector<double> med[2];  // [schlick derived, f82 fitted] over metals, for the reading
  int clamped_rows = 0;
  for (const auto& s : studies)
    for (const auto& r : s.models)
      for (int fitted = 0; fitted < 2; ++fitted) {
        clamped_rows += fitted ? r.fitted_clamps : r.derived_clamps;
        t.rows.push_back(models_row(s, r, fitted));
        // The talk's comparison: Schlick as derived (spectral F0) against the fitted F82 model.
        const bool schlick_derived =
            r.model == fresnel::model_of<fresnel::models::Schlick> && !fitted;
        const bool f82_fitted = r.model == fresnel::model_of<fresnel::models::F82> && fitted;
        if (s.is_metal() && (schlick_derived || f82_fitted))
          med[f82_fitted].push_back(fitted ? r.fitted_error.rms : r.derived_error.rms);
      }
  const double m_schlick = median(med[0]), m_f82 = median(med[1]);
  t.reading = fmt::format(
      "Over the {} metals the fitted F82 model's median RMS ΔE2000 is {:.3f} against Schlick's "
      "(spectral F0) {:.3f} "
      "({:.1f}× lower). "
      "Derived parameters come straight from the spectral procedure; fitted ones minimize each "
      "material's error.",
      med[1].size(), m_f82, m_schlick, m_schlick / m_f82);
  t.notes = {setting_note(ctx),
             "rms_weighted_de00 weights each angle by sinθ·cosθ, the share of a sphere's image "
             "that sees it.",
             fmt::format(
                 "clamped: the F82 model's result left [0, 1] somewhere and was clamped ({} rows).",
                 clamped_rows),
             "Derived: Schlick F0; generalized Schlick F0, F90 = 1, p through F82; Cook-Torrance "
             "F0 with the luminance "
             "of Refl. η, κ as representative index; Lazányi F0, a from F82, α = 6; F82 model F0, "
             "F82; Gulbrandsen F0 "
             "and g from Refl. η; RGB Fresnel Refl. η, κ.",
             fit_flags_note(studies),
             coverage_note(materials_of(studies))};
  return t;
}

Table catalog_table(const spectral::DataPaths& paths) {
  Table t;
  t.name = "materials";
  t.title = "Material catalog";
  t.columns = {{"key"}, {"material"}, {"class"}, {"source"}, {"reference"}};
  for (const auto& m : spectral::read_catalog(paths))
    t.rows.push_back(
        {m.key, m.name, std::string(spectral::to_string(m.material_class)), m.source, m.reference});
  return t;
}

}  // namespace fl::analysis
