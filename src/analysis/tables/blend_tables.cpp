#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/study/table_notes.h"
#include "analysis/tables/media_tables.h"
#include "color/ciede2000_batch.h"
#include "fresnel/exact.h"
#include "fresnel/media.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "util/errors.h"

namespace fl::analysis {

using fresnel::Model;

namespace {

double rms(const std::vector<double>& v) {
  double ss = 0;
  for (double x : v) ss += x * x;
  return std::sqrt(ss / v.size());
}

std::vector<color::Rgb> lerp_curves(const std::vector<color::Rgb>& a,
                                    const std::vector<color::Rgb>& b, double w) {
  std::vector<color::Rgb> out(a.size());
  for (size_t i = 0; i < a.size(); ++i) out[i] = (1.0 - w) * a[i] + w * b[i];
  return out;
}

std::vector<double> lerp_params(const std::vector<double>& a, const std::vector<double>& b,
                                double w) {
  std::vector<double> out(a.size());
  for (size_t i = 0; i < a.size(); ++i) out[i] = (1.0 - w) * a[i] + w * b[i];
  return out;
}

// The metals' index lists to blend: pairs (i < j), or chains of N consecutive metals.
std::vector<std::vector<size_t>> blend_groups(const std::vector<MaterialStudy>& studies,
                                              const BlendOptions& o) {
  if (!(o.weight >= 0.0 && o.weight <= 1.0)) throw InputError("--blend-weight must be in [0, 1]");
  std::vector<size_t> metals;
  for (size_t i = 0; i < studies.size(); ++i)
    if (studies[i].is_metal()) metals.push_back(i);
  if (o.chain < 2 || o.chain > static_cast<int>(metals.size()))
    throw InputError(fmt::format("--blend-chain must be between 2 and the number of metals ({})",
                                 metals.size()));
  std::vector<std::vector<size_t>> groups;
  if (o.chain == 2) {
    for (size_t i = 0; i < metals.size(); ++i)
      for (size_t j = i + 1; j < metals.size(); ++j) groups.push_back({metals[i], metals[j]});
  } else {
    for (size_t i = 0; i < metals.size(); ++i) {
      std::vector<size_t> g;
      for (int k = 0; k < o.chain; ++k) g.push_back(metals[(i + k) % metals.size()]);
      groups.push_back(g);
    }
  }
  return groups;
}

// Blends a group in turn (result = lerp(result, next, w)), as curves (A) and as parameters (B).
double blend_error(const Context& ctx, Model m, const std::vector<std::vector<double>>& params,
                   double w) {
  const auto& cos = ctx.cos_thetas();
  auto curve_a = fresnel::evaluate_curve_unclamped(m, params[0], cos);
  auto p = params[0];
  for (size_t k = 1; k < params.size(); ++k) {
    curve_a = lerp_curves(curve_a, fresnel::evaluate_curve_unclamped(m, params[k], cos), w);
    p = lerp_params(p, params[k], w);
  }
  return rms(de2000_per_angle(ctx, curve_a, fresnel::evaluate_curve_unclamped(m, p, cos)));
}

std::string group_name(const std::vector<MaterialStudy>& studies, const std::vector<size_t>& g,
                       size_t from) {
  std::string s;
  for (size_t k = from; k < g.size(); ++k)
    s += (k > from ? " > " : "") + studies[g[k]].material->material.name;
  return s;
}

std::string blend_note(const BlendOptions& o) {
  return o.chain == 2
             ? fmt::format("Every pair of metals, blended with weight {:g} on the second.",
                           o.weight)
             : fmt::format(
                   "Chains of {} consecutive metals (catalog order, wrapping), each blended into "
                   "the running result with weight {:g}.",
                   o.chain, o.weight);
}

}  // namespace

Table blend_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                  const BlendOptions& o) {
  Table t;
  t.name = "blend";
  t.title =
      "Parameter blending: Gulbrandsen (F0, g), RMS ΔE2000 between blended curves and blended "
      "parameters";
  t.columns = {{"material_a"}, {"material_b"}, {"de00", 3}};
  std::vector<std::pair<double, std::vector<size_t>>> rows;
  for (const auto& g : blend_groups(studies, o)) {
    std::vector<std::vector<double>> p;
    for (size_t i : g)
      p.push_back(studies[i].result(fresnel::model_of<fresnel::models::Gulbrandsen>).derived);
    rows.emplace_back(
        blend_error(ctx, fresnel::model_of<fresnel::models::Gulbrandsen>, p, o.weight), g);
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [de, g] : rows)
    t.rows.push_back({studies[g[0]].material->material.name, group_name(studies, g, 1), de});
  t.reading = fmt::format(
      "Blending Gulbrandsen's (F0, g) parameters is not the same as blending the reflectances they "
      "produce: the worst "
      "pair differs by {:.2f} ΔE2000 (RMS over angles). Schlick and the F82 model are linear in "
      "their parameters, so "
      "for them the two agree exactly (see blend_models).",
      rows.empty() ? 0.0 : rows.front().first);
  t.notes = {blend_note(o),
             "Case A evaluates each material's curve and blends the results; case B blends the "
             "parameters and "
             "evaluates once. Parameters: F0 spectral, g from (F0, Refl. η) (the talk's \"Refl. F0 "
             "+ Refl. η\")."};
  return t;
}

Table blend_models_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                         const BlendOptions& o) {
  Table t;
  t.name = "blend_models";
  t.title = "Parameter blending for every model (derived parameters), RMS ΔE2000";
  t.columns = {{"material_a"}, {"material_b"}};
  for (const auto& spec : fresnel::model_specs()) t.columns.push_back({spec.name, 3});
  std::vector<double> worst(fresnel::model_specs().size(), 0.0);
  for (const auto& g : blend_groups(studies, o)) {
    std::vector<Cell> row{studies[g[0]].material->material.name, group_name(studies, g, 1)};
    size_t k = 0;
    for (const auto& spec : fresnel::model_specs()) {
      std::vector<std::vector<double>> p;
      for (size_t i : g) p.push_back(studies[i].result(spec.model).derived);
      const double de = blend_error(ctx, spec.model, p, o.weight);
      worst[k] = std::max(worst[k], de);
      ++k;
      row.push_back(de);
    }
    t.rows.push_back(std::move(row));
  }
  std::string w;
  for (size_t k = 0; k < worst.size(); ++k)
    w += fmt::format("{}{} {:.3g}", k ? ", " : "", fresnel::model_specs()[k].name, worst[k]);
  t.reading =
      "Models linear in their parameters (Schlick, the F82 model, Lazányi with fixed α) blend "
      "exactly; "
      "the others do not. Worst pair per model: " +
      w + ".";
  t.notes = {
      blend_note(o), "Derived parameters of each model (see the models table), 12 decimals.",
      "The F82 model is evaluated without its [0, 1] output clamp (a range guard) in both cases."};
  for (auto& c : t.columns)
    if (c.precision == 3) c.precision = 12;
  return t;
}

namespace {

struct GamutResult {
  double de = 0;
  int moved = 0;         // converted channels that left the model's domain (clamped back)
  int outside_unit = 0;  // converted reflectance channels (F0, F82, F90) outside [0, 1] (kept)
};

GamutResult gamut_error(const Context& ctx, Model m, const std::vector<double>& params,
                        const color::Mat3& conv, const color::LabConverter& to_lab) {
  const auto& spec = fresnel::model_spec(m);
  const int pc = spec.per_channel();
  const auto& cos = ctx.cos_thetas();
  // Case A: evaluate in the working space, convert the result.
  std::vector<color::Rgb> a;
  for (const auto& rgb : fresnel::evaluate_curve_unclamped(m, params, cos))
    a.push_back(color::transform_rgb(conv, rgb));
  // Case B: convert each per-channel parameter as a colour, evaluate in the target space.
  auto p = params;
  for (int j = 0; j < pc; ++j) {
    const color::Rgb v =
        color::transform_rgb(conv, {params[j], params[pc + j], params[2 * pc + j]});
    for (int ch = 0; ch < 3; ++ch) p[ch * pc + j] = v[ch];
  }
  GamutResult r;
  r.outside_unit = fresnel::reflectances_outside_unit(m, p);
  r.moved = fresnel::clamp_to_domain(m, p);
  const auto b = fresnel::evaluate_curve_unclamped(m, p, cos);
  std::vector<color::Lab> lab_a, lab_b;
  for (const auto& c : a) lab_a.push_back(to_lab(c));
  for (const auto& c : b) lab_b.push_back(to_lab(c));
  std::vector<double> de(a.size());
  color::ciede2000_batch(lab_a, lab_b, de);
  r.de = rms(de);
  return r;
}

const std::vector<std::string>& gamut_targets() {
  static const std::vector<std::string> t{"lin_rec709", "aces2065-1"};
  return t;
}

}  // namespace

Table gamut_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  Table t;
  t.name = "gamut";
  t.title = fmt::format(
      "Gamut conversion: Gulbrandsen (F0, g) derived in {}, RMS ΔE2000 in the target space",
      ctx.settings().space);
  t.columns = {{"material"}, {"rec709", 3}, {"ap0", 3}, {"channels_clamped", 0, false}};
  add_coverage_columns(t);
  std::vector<color::Mat3> conv;
  std::vector<color::LabConverter> lab;
  for (const auto& target : gamut_targets()) {
    conv.push_back(ctx.spaces().conversion(ctx.settings().space, target));
    const auto sp = ctx.spaces().space(target);
    lab.push_back({sp.rgb_to_xyz, sp.white});
  }
  int total = 0;
  double worst = 0;
  for (const auto& s : studies) {
    std::vector<Cell> row{s.material->material.name};
    long long moved = 0;
    for (size_t k = 0; k < conv.size(); ++k) {
      const auto r = gamut_error(ctx, fresnel::model_of<fresnel::models::Gulbrandsen>,
                                 s.result(fresnel::model_of<fresnel::models::Gulbrandsen>).derived,
                                 conv[k], lab[k]);
      row.push_back(r.de);
      moved += r.moved;
      worst = std::max(worst, r.de);
    }
    total += static_cast<int>(moved);
    row.push_back(moved);
    add_coverage_cells(row, *s.material);
    t.rows.push_back(std::move(row));
  }
  t.reading = fmt::format(
      "Converting Gulbrandsen's parameters to another RGB space is not the same as converting its "
      "result (worst "
      "{:.2f} ΔE2000); Schlick and the F82 model convert exactly (see gamut_models).",
      worst);
  t.notes = {
      "Case A evaluates in the working space and converts the resulting RGB with OpenColorIO's "
      "matrix; case B "
      "converts F0 and g as colours and evaluates in the target space. Lab relative to the "
      "target's white.",
      fmt::format("Converted parameters can leave the model's domain (F0 < 0 or ≥ 1, g outside [0, "
                  "1]); they "
                  "are clamped into it and counted in channels_clamped: {} channels in all.",
                  total),
      coverage_note(materials_of(studies))};
  return t;
}

Table gamut_models_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  Table t;
  t.name = "gamut_models";
  t.title = "Gamut conversion for every model (derived parameters), RMS ΔE2000 in the target space";
  t.columns = {{"material"}, {"target"}};
  for (const auto& spec : fresnel::model_specs()) t.columns.push_back({spec.name, 12});
  t.columns.push_back({"channels_clamped", 0});
  t.columns.push_back({"reflectances_outside_unit", 0});
  add_coverage_columns(t);
  int total = 0, outside = 0;
  for (const auto& target : gamut_targets()) {
    const auto conv = ctx.spaces().conversion(ctx.settings().space, target);
    const auto sp = ctx.spaces().space(target);
    const color::LabConverter lab{sp.rgb_to_xyz, sp.white};
    for (const auto& s : studies) {
      std::vector<Cell> row{s.material->material.name, target};
      long long moved = 0, out_unit = 0;
      for (const auto& spec : fresnel::model_specs()) {
        const auto r = gamut_error(ctx, spec.model, s.result(spec.model).derived, conv, lab);
        row.push_back(r.de);
        moved += r.moved;
        out_unit += r.outside_unit;
      }
      total += static_cast<int>(moved);
      outside += static_cast<int>(out_unit);
      row.push_back(moved);
      row.push_back(out_unit);
      add_coverage_cells(row, *s.material);
      t.rows.push_back(std::move(row));
    }
  }
  t.reading =
      "Schlick, the F82 model and Lazányi are linear in their colour parameters and commute with a "
      "linear "
      "change of primaries; Gulbrandsen, the RGB Fresnel equations and the exponent models do not.";
  t.notes = {
      "Every per-channel parameter is converted as a colour (what a pipeline that converts "
      "textures does); "
      "shared parameters (Cook-Torrance's representative index) are kept.",
      fmt::format("Parameters that leave a model's domain are clamped into it (clamp_to_domain) "
                  "and counted: "
                  "{} channels.",
                  total),
      fmt::format("Reflectance parameters (F0, F82, F90) outside [0, 1] after conversion are kept "
                  "(Schlick and the "
                  "F82 formula are defined there; e.g. gold's F0 lies outside the Rec.709 gamut) "
                  "and counted: {}. "
                  "Both cases evaluate the F82 model without its [0, 1] output clamp, a range "
                  "guard that would "
                  "otherwise break its linearity.",
                  outside),
      coverage_note(materials_of(studies))};
  return t;
}

}  // namespace fl::analysis
