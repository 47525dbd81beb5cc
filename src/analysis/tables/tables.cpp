#include "analysis/tables/tables.h"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/tables/lut_accuracy.h"
#include "analysis/tables/shading_presets.h"
#include "fresnel/average.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"
#include "util/quantile.h"

namespace fl::analysis {

namespace {

std::vector<color::Rgb> schlick_curve(const Context& ctx, const color::Rgb& f0) {
  return fresnel::evaluate_curve(fresnel::model_of<fresnel::models::Schlick>, {f0.r, f0.g, f0.b},
                                 ctx.cos_thetas());
}

}  // namespace

std::string out_of_range_note(int flagged) {
  return fmt::format(
      "out_of_range: the values below 0 or above 1 by more than {:g}, kept unclamped; {} materials "
      "flagged.",
      kOutOfRangeTolerance, flagged);
}

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

std::vector<const LoadedMaterial*> materials_of(const std::vector<MaterialStudy>& studies) {
  std::vector<const LoadedMaterial*> out;
  for (const auto& s : studies) out.push_back(s.material);
  return out;
}

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

std::string model_names() {
  std::string s;
  for (const auto& m : fresnel::model_specs()) s += (s.empty() ? "" : ", ") + std::string(m.name);
  return s;
}

MaterialStudy study_one(const Context& ctx, const std::vector<LoadedMaterial>& one,
                        const std::string& kind, const std::vector<fresnel::Model>& models) {
  const ParameterSet set = parameter_set_from_name(kind);
  StudyOptions o;
  o.fit = set != ParameterSet::Derived;
  o.fitted_models = models;
  o.threads = 1;
  MaterialStudy st = study_materials(ctx, one, o).front();
  if (set == ParameterSet::Rendered) add_rendered_fits(ctx, st, lut_accuracy_points(), models);
  return st;
}

const std::vector<double>& model_params(const MaterialStudy& st, fresnel::Model m,
                                        const std::string& kind) {
  const auto& r = st.result(m);
  switch (parameter_set_from_name(kind)) {
    case ParameterSet::Fitted:
      return r.fitted.parameters;
    case ParameterSet::Rendered:
      return r.rendered.parameters;
    case ParameterSet::Derived:
      break;
  }
  return r.derived;
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

std::string fit_flags_note(const std::vector<MaterialStudy>& studies) {
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

bool is_metal(const MaterialStudy& s) {
  return s.material->material.material_class == spectral::MaterialClass::Metal;
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
    if (!is_metal(s)) continue;
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
  add_coverage_cells(row, *s.material);
  row.push_back(fitted ? fit::fit_flags(r.fitted) : std::string());
  return row;
}

}  // namespace

Table models_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
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
        if (is_metal(s) && (schlick_derived || f82_fitted))
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

namespace {

// The F82 model's hemispherical average from the spectral F0 and F82: OpenPBR's F82-tint average
// albedo, for Kulla–Conty energy compensation.
color::Rgb f82_average(const fresnel::DerivedParameters& d) {
  std::vector<double> p;
  for (int c = 0; c < 3; ++c) p.insert(p.end(), {d.f0[c], d.f82[c]});
  return fresnel::hemispherical_average(fresnel::model_of<fresnel::models::F82>, p);
}
constexpr const char* kF82AverageNote =
    "f_avg (Markdown and JSON only): the F82 model's hemispherical average 2∫F(μ)μ dμ = F0 + (1 − "
    "F0)/21 − a/126 "
    "from the spectral F0 and F82 (OpenPBR's F82-tint average albedo), for Kulla–Conty "
    "multiple-scattering "
    "compensation.";
void add_f_avg_columns(Table& t) {
  for (const char* c : {"r", "g", "b"}) t.columns.push_back({fmt::format("f_avg_{}", c), 6, false});
}
void add_f_avg(std::vector<Cell>& row, const fresnel::DerivedParameters& d) {
  const auto f_avg = f82_average(d);
  for (int c = 0; c < 3; ++c) row.push_back(f_avg[c]);
}

// A basis model's coefficients per channel (its derived set: the projection of the ground truth on
// the basis), named like the model's parameters: basis4_c0_r, ...
void add_basis_columns(Table& t, fresnel::Model basis) {
  for (const auto& name : fresnel::model_spec(basis).param_names())
    t.columns.push_back({fmt::format("{}_{}", fresnel::model_spec(basis).name, name), 6});
}
void add_basis(std::vector<Cell>& row, const MaterialStudy& s, fresnel::Model basis) {
  for (double c : s.result(basis).derived) row.push_back(c);
}
std::string basis_note(int terms) {
  std::string span = "1, (1 − μ)⁵", sum = "c0 + c1·(1 − μ)⁵";
  for (int k = 2; k < terms; ++k) {
    span += fmt::format(", b{}", k);
    sum += fmt::format(" + c{}·b{}(μ)", k, k);
  }
  return fmt::format(
      "basis{0}_c*: the basis{0} model's coefficients per channel on the Fresnel basis {{{1}}} "
      "(docs/basis.md), F = {2}: the least-squares projection of the ground truth, "
      "pre-integrated through the dfg/dfg_2 and ltc_2/ltc_3 tables.",
      terms, span, sum);
}

}  // namespace

std::string page_kind_text(const spectral::Material& m) {
  if (m.origin == spectral::Material::Origin::Consensus) return "consensus";
  if (m.page_class.kind == spectral::PageKind::Unlisted &&
      m.origin != spectral::Material::Origin::Page)
    return {};
  const auto& c = m.page_class;
  return std::string(spectral::to_string(c.kind)) + (c.detail.empty() ? "" : " " + c.detail);
}

Table presets_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                    int basis_terms) {
  const auto basis = fresnel::model_from_name(fmt::format("basis{}", basis_terms)).model;
  Table t;
  t.name = "presets";
  t.title = fmt::format("Material presets in {}", ctx.settings().space);
  t.columns = {{"material"}, {"class"}, {"space"}};
  for (const char* q : {"f0", "f82", "g", "eta", "kappa"})
    for (const char* c : {"r", "g", "b"}) t.columns.push_back({fmt::format("{}_{}", q, c), 6});
  add_f_avg_columns(t);
  add_basis_columns(t, basis);
  t.columns.push_back({"out_of_range"});
  add_coverage_columns(t);
  t.columns.insert(t.columns.end(), {{"fit_flags"}, {"page_kind"}});
  int flagged = 0;
  for (const auto& s : studies) {
    const auto& d = s.derived;
    const auto& eta_kappa = s.result(fresnel::model_of<fresnel::models::FresnelRgb>);
    const auto& ek =
        eta_kappa.fitted.parameters.empty() ? eta_kappa.derived : eta_kappa.fitted.parameters;
    std::vector<Cell> row{s.material->material.name,
                          std::string(spectral::to_string(s.material->material.material_class)),
                          ctx.settings().space};
    for (const auto* v : {&d.f0, &d.f82, &d.g_refl_eta})
      for (int c = 0; c < 3; ++c) row.push_back((*v)[c]);
    for (int c = 0; c < 3; ++c) row.push_back(ek[2 * c]);
    for (int c = 0; c < 3; ++c) row.push_back(ek[2 * c + 1]);
    add_f_avg(row, d);
    add_basis(row, s, basis);
    NamedValues unit;
    add_channels(unit, "f0", d.f0);
    add_channels(unit, "f82", d.f82);
    add_channels(unit, "g", d.g_refl_eta);
    const std::string flags = out_of_range_list(unit);
    flagged += flags.empty() ? 0 : 1;
    row.push_back(flags);
    add_coverage_cells(row, *s.material);
    row.push_back(eta_kappa.fitted.parameters.empty() ? std::string()
                                                      : fit::fit_flags(eta_kappa.fitted));
    row.push_back(page_kind_text(s.material->material));
    t.rows.push_back(std::move(row));
  }
  t.reading = "Parameters for shading models, per material, in the working space.";
  t.notes = {
      setting_note(ctx),
      "F0, F82: the spectral procedure at 0° and at arccos(1/7) ≈ 81.79°.",
      "g: Gulbrandsen's edge tint from (F0, Refl. η), unclamped.",
      "eta, kappa: RGB η, κ fitted with Ceres to minimize the RMS ΔE2000 against ground truth.",
      kF82AverageNote,
      basis_note(basis_terms),
      out_of_range_note(flagged),
      "fit_flags: of the eta, kappa fit (see the models table's notes).",
      "page_kind: a database page's kind from the catalog (bulk, thin film, nanostructure, model, "
      "computed, variant; docs/consensus.md), with a film's thickness or a temperature; "
      "\"consensus\" for a consensus preset.",
      coverage_note(materials_of(studies))};
  return t;
}

StudyOptions presets_study_options(bool openpbr) {
  StudyOptions o;
  o.fit = !openpbr;
  o.fitted_models = {fresnel::model_of<fresnel::models::FresnelRgb>};
  return o;
}

Table openpbr_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  Table t;
  t.name = "presets_openpbr";
  t.title = fmt::format("OpenPBR presets in {}", ctx.settings().space);
  t.columns = {{"material"}};
  for (const char* q : {"base_color", "specular_color"})
    for (const char* c : {"r", "g", "b"}) t.columns.push_back({fmt::format("{}_{}", q, c), 6});
  t.columns.insert(
      t.columns.end(),
      {{"base_weight", 0}, {"base_metalness", 0}, {"specular_ior", 6}, {"transmission_weight", 0}});
  add_f_avg_columns(t);
  t.columns.push_back({"out_of_range"});
  add_coverage_columns(t);
  int flagged = 0;
  for (const auto& s : studies) {
    const auto o = open_pbr_parameters(shading_preset(ctx, s));
    std::vector<Cell> row{s.material->material.name};
    for (int c = 0; c < 3; ++c) row.push_back(o.base_color[c]);
    for (int c = 0; c < 3; ++c) row.push_back(o.specular_color[c]);
    row.insert(row.end(), {o.base_weight, o.base_metalness, o.specular_ior, o.transmission_weight});
    add_f_avg(row, s.derived);
    NamedValues unit;
    add_channels(unit, "base_color", o.base_color);
    add_channels(unit, "specular_color", o.specular_color);
    const std::string flags = out_of_range_list(unit);
    flagged += flags.empty() ? 0 : 1;
    row.push_back(flags);
    add_coverage_cells(row, *s.material);
    t.rows.push_back(std::move(row));
  }
  t.reading =
      "OpenPBR Surface parameters. Metals: base_metalness 1, base_color = F0, specular_color = the "
      "ratio of "
      "the true F82 to Schlick's value at arccos(1/7) (a tint above 1: the true curve is brighter "
      "there than "
      "Schlick's). Dielectrics: base_metalness 0, specular_ior = the index whose normal-incidence "
      "reflectance "
      "is F0's luminance, transmission_weight 1 when clear (κ ≤ 1e-4 over the visible), "
      "base_weight 0 when "
      "opaque; their base_color and a metal's specular_ior are unused and keep OpenPBR's defaults.";
  t.notes = {setting_note(ctx), kF82AverageNote, out_of_range_note(flagged),
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
