#include "analysis/presets/preset_tables.h"

#include <fmt/format.h>

#include "analysis/presets/shading_presets.h"
#include "analysis/study/table_notes.h"
#include "fresnel/average.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"

namespace fl::analysis {

namespace {

// The out-of-range policy in one sentence, with the number of materials flagged.
std::string out_of_range_note(int flagged) {
  return fmt::format(
      "out_of_range: the values below 0 or above 1 by more than {:g}, kept unclamped; {} materials "
      "flagged.",
      kOutOfRangeTolerance, flagged);
}

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
  std::string span = "1", sum = "c0";
  for (int k = 1; k < terms; ++k) {
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

}  // namespace fl::analysis
