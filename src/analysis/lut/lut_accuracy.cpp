#include "analysis/lut/lut_accuracy.h"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/lut/rendered_fit.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "util/parallel.h"
#include "util/quantile.h"

namespace fl::analysis {

using fresnel::Model;

namespace {

fit::FitResult rendered_fit(const Context& ctx, const MaterialStudy& study, const ModelResult& r,
                            const std::vector<color::Rgb>& truth,
                            const std::vector<ShadingPoint>& points) {
  std::vector<std::vector<double>> starts{r.derived};
  if (r.fitted.usable && !r.fitted.parameters.empty()) starts.push_back(r.fitted.parameters);
  return fit_rendered(ctx, truth, r.model, points, std::move(starts), study.lossless);
}

// A page's truth at the points, in RGB (what the rendered fits match) and in CIELAB.
struct PageTruth {
  std::vector<color::Rgb> rgb;
  std::vector<color::Lab> lab;
};

RenderedCandidate candidate(const Context& ctx, const ModelResult& r, ParameterSet set,
                            std::vector<double> params, double punctual_rms, const PageTruth& truth,
                            const std::vector<ShadingPoint>& points) {
  RenderedCandidate c;
  c.model = r.model;
  c.set = set;
  c.params = std::move(params);
  c.punctual_rms = punctual_rms;
  c.ibl = error_stats(rendered_de00(ctx, truth.lab, r.model, c.params, Lighting::Ibl, points));
  c.area = error_stats(rendered_de00(ctx, truth.lab, r.model, c.params, Lighting::Area, points));
  c.ibl_table = error_stats(table_de00(ctx, r.model, c.params, Lighting::Ibl, points));
  c.area_table = error_stats(table_de00(ctx, r.model, c.params, Lighting::Area, points));
  for (size_t w = 0; w < kProjectedWays.size(); ++w) {
    const EngineWay way = kProjectedWays[w];
    if (projected_span(way).empty()) {
      c.ibl_ways[w] =
          error_stats(rendered_de00(ctx, truth.lab, r.model, c.params, Lighting::Ibl, points, way))
              .rms;
      c.area_ways[w] =
          error_stats(rendered_de00(ctx, truth.lab, r.model, c.params, Lighting::Area, points, way))
              .rms;
      continue;
    }
    // The curve projected on the span once, shaded under both lightings.
    const auto weights = projected_weights(ctx, r.model, c.params, projected_span(way));
    c.ibl_ways[w] =
        error_stats(rendered_de00_terms(ctx, truth.lab, weights, Lighting::Ibl, points)).rms;
    c.area_ways[w] =
        error_stats(rendered_de00_terms(ctx, truth.lab, weights, Lighting::Area, points)).rms;
  }
  return c;
}

// One model's candidates: its derived and fitted sets, and its set fitted to the render.
std::vector<RenderedCandidate> model_candidates(const Context& ctx, const MaterialStudy& study,
                                                const ModelResult& r, const PageTruth& truth,
                                                const fit::CurveTarget& target,
                                                const std::vector<ShadingPoint>& points) {
  std::vector<RenderedCandidate> out;
  out.push_back(
      candidate(ctx, r, ParameterSet::Derived, r.derived, r.derived_error.rms, truth, points));
  if (r.fitted.usable && !r.fitted.parameters.empty())
    out.push_back(candidate(ctx, r, ParameterSet::Fitted, r.fitted.parameters, r.fitted_error.rms,
                            truth, points));
  const auto rendered = rendered_fit(ctx, study, r, truth.rgb, points);
  if (!rendered.usable) return out;
  const auto curve = fresnel::evaluate_curve(r.model, rendered.parameters, ctx.cos_thetas());
  out.push_back(candidate(ctx, r, ParameterSet::Rendered, rendered.parameters,
                          curve_error(ctx, target.truth_lab, curve).rms, truth, points));
  return out;
}

}  // namespace

std::vector<RenderedCandidate> rendered_candidates(const Context& ctx, const MaterialStudy& study,
                                                   const std::vector<ShadingPoint>& points) {
  PageTruth truth;
  truth.rgb = lobe_truth(ctx, *study.material, points);
  truth.lab = lab_curve(ctx, truth.rgb);
  const auto target = curve_target(ctx, study.truth);
  // The models side by side: a material's rendered fits differ in cost by 100× (flat valleys).
  std::vector<std::vector<RenderedCandidate>> per_model(study.models.size());
  parallel_for_all(per_model.size(), [&](size_t k) {
    per_model[k] = model_candidates(ctx, study, study.models[k], truth, target, points);
  });
  std::vector<RenderedCandidate> out;
  for (auto& cs : per_model)
    for (auto& c : cs) out.push_back(std::move(c));
  return out;
}

void add_rendered_fits(const Context& ctx, MaterialStudy& study,
                       const std::vector<ShadingPoint>& points,
                       const std::vector<fresnel::Model>& models) {
  const auto truth = lobe_truth(ctx, *study.material, points);
  for (auto& r : study.models)
    if (models.empty() || std::find(models.begin(), models.end(), r.model) != models.end())
      r.rendered = rendered_fit(ctx, study, r, truth, points);
}

namespace {

std::string approximation(Model m, Lighting l) {
  const auto& s = lighting_support(m, l);
  return s.fresnel_pre_integrated ? "tables" : fmt::format("F({}) × lobe", s.evaluated_at);
}

const RenderedCandidate* find(const std::vector<RenderedCandidate>& cs, Model m, ParameterSet set) {
  for (const auto& c : cs)
    if (c.model == m && c.set == set) return &c;
  return nullptr;
}

// "F82 ≤ Schlick for k of n metals" under one lighting, derived parameter sets (spectral F0, F82).
std::string f82_against_schlick(const std::vector<std::vector<RenderedCandidate>>& per_metal,
                                Lighting l) {
  int no_worse = 0;
  std::vector<double> schlick, f82;
  for (const auto& cs : per_metal) {
    const auto* s = find(cs, fresnel::model_of<fresnel::models::Schlick>, ParameterSet::Derived);
    const auto* f = find(cs, fresnel::model_of<fresnel::models::F82>, ParameterSet::Derived);
    no_worse += f->under(l).rms <= s->under(l).rms;
    schlick.push_back(s->under(l).rms);
    f82.push_back(f->under(l).rms);
  }
  return fmt::format(
      "under {}, pre-integrated F82 is no worse than pre-integrated Schlick for {} of {} metals "
      "(median RMS ΔE2000 {:.3f} against {:.3f})",
      lighting_name(l), no_worse, per_metal.size(), median(f82), median(schlick));
}

// "F82 fitted to the render: median RMS ΔE2000 under ibl, metals 0.30 → 0.25, ..." (derived →
// rendered) per class and lighting.
std::string rendered_gain(const std::vector<MaterialStudy>& studies,
                          const std::vector<std::vector<RenderedCandidate>>& per_material) {
  std::string out = "F82 fitted to the render against F82 derived, median RMS ΔE2000:";
  const Model f82 = fresnel::model_of<fresnel::models::F82>;
  for (const Lighting l : {Lighting::Ibl, Lighting::Area})
    for (const auto cls : {spectral::MaterialClass::Metal, spectral::MaterialClass::Dielectric}) {
      std::vector<double> derived, rendered;
      for (size_t i = 0; i < studies.size(); ++i) {
        if (studies[i].material->material.material_class != cls) continue;
        const auto* d = find(per_material[i], f82, ParameterSet::Derived);
        const auto* r = find(per_material[i], f82, ParameterSet::Rendered);
        if (!d || !r) continue;
        derived.push_back(d->under(l).rms);
        rendered.push_back(r->under(l).rms);
      }
      if (derived.empty()) continue;
      out +=
          fmt::format(" {} {}s {:.3f} → {:.3f} ({});", lighting_name(l), spectral::to_string(cls),
                      median(derived), median(rendered), derived.size());
    }
  out.back() = '.';
  return out;
}

// "Models no shared table holds, derived sets, median RMS ΔE2000 at n·v → Hoffman span → basis
// span: ibl metals 3.10 → 0.41 → 0.18; ..." per lighting and class.
std::string projection_gain(const std::vector<MaterialStudy>& studies,
                            const std::vector<std::vector<RenderedCandidate>>& per_material) {
  std::string out =
      "Projected on the tables' terms, the derived sets of the models no shared table holds "
      "render, median RMS ΔE2000 at n·v → Hoffman span → basis span:";
  for (const Lighting l : {Lighting::Ibl, Lighting::Area})
    for (const auto cls : {spectral::MaterialClass::Metal, spectral::MaterialClass::Dielectric}) {
      std::array<std::vector<double>, 3> ways;
      for (size_t i = 0; i < studies.size(); ++i) {
        if (studies[i].material->material.material_class != cls) continue;
        for (const auto& c : per_material[i]) {
          if (c.set != ParameterSet::Derived || lighting_support(c.model, l).fresnel_pre_integrated)
            continue;
          for (size_t w = 0; w < ways.size(); ++w)
            ways[w].push_back(l == Lighting::Ibl ? c.ibl_ways[w] : c.area_ways[w]);
        }
      }
      if (ways[0].empty()) continue;
      out += fmt::format(" {} {}s {:.3f} → {:.3f} → {:.3f} ({} model × material pairs);",
                         lighting_name(l), spectral::to_string(cls), median(ways[0]),
                         median(ways[1]), median(ways[2]), ways[0].size());
    }
  out.back() = '.';
  return out;
}

std::vector<std::string> accuracy_notes(const Context& ctx) {
  std::string roughness_list, view_list;
  for (double r : kDefaultRoughness)
    roughness_list += (roughness_list.empty() ? "" : ", ") + fmt::format("{:g}", r);
  for (double d : kShadingViewDeg)
    view_list += (view_list.empty() ? "" : ", ") + fmt::format("{:g}°", d);
  const auto& s = ctx.settings();
  return {
      fmt::format("Working space {}, illuminant {}, {} adaptation, outside medium η = {:g}.",
                  s.space, s.illuminant, s.adaptation, s.eta_outside),
      fmt::format(
          "Shading points: perceptual roughness {} (α = roughness²) × view angle {}; per point the "
          "GGX lobe "
          "(height-correlated Smith) is integrated with {} visible-normal samples (Hammersley).",
          roughness_list, view_list, kLutSamples),
      fmt::format("Truth: the lobe integrated with the spectral Fresnel ground truth per v·h (RGB "
                  "at {} values of cos θ, interpolated per sample by polynomials of degree {} on "
                  "{} panels that narrow towards grazing; within 5e-5 of the spectral curve at "
                  "every sample).",
                  kTruthNodes, kTruthDegree, kTruthPanelEdges.size() - 1),
      fmt::format(
          "Engine: the {0}² tables as `lut` writes them (32-bit floats), read bilinearly (DFG at "
          "(n·v, roughness), LTC moments at (roughness, √(1 − n·v)), both on endpoints: the edge "
          "texels hold the axes' ends). `tables`: the Fresnel "
          "term is "
          "pre-integrated, a·n + b·f + c·l with F = a + b(1 − μ)⁵ + cμ(1 − μ)⁶ (Schlick: F0·dfg1 + "
          "dfg2; "
          "F82: … − a·dfg_f82, unclamped); `F(n·v) × lobe`: the model at n·v times the lobe's "
          "Fresnel-free "
          "integral (dfg1 + dfg2, n_D), the stated approximation for models no shared table holds.",
          kEngineLutSize),
      "curve_rms_de00: the curve's RMS ΔE2000 over the angles, what punctual lights render. rms "
      "and max: over the "
      "shading points. ibl_table and area_table: the tables' own error, the same shading from the "
      "tables against from the exact integrals at each point (RMS). The lobe's shape (LTC matrix, "
      "prefiltered environment) is the same for "
      "every model and not "
      "part of these errors.",
      "ibl_nv, ibl_hoffman, ibl_basis (and area_…): every model rendered three ways whatever "
      "its own shader does: F(n·v) × lobe; its RGB curve projected (least squares per channel "
      "over the angles) on Hoffman's span {1, (1 − μ)⁵, μ(1 − μ)⁶}, pre-integrated by those "
      "tables; and projected on the 5-term basis {1, b1, b2, b3, b4}, pre-integrated by its "
      "tables.",
      "rendered: parameters fitted to these errors (½ Σ ΔE2000² over both lightings and every "
      "shading point, from the derived and fitted sets), not to the curve; its curve_rms_de00 is "
      "the curve of those parameters."};
}

}  // namespace

std::vector<ShadingPoint> lut_accuracy_points() {
  return shading_points({kDefaultRoughness.begin(), kDefaultRoughness.end()});
}

Table lut_accuracy_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                         const std::vector<ShadingPoint>& points) {
  Table t;
  t.name = "lut-accuracy";
  t.title =
      "Fresnel models as rendered under IBL (DFG) and area lights (LTC moments) against "
      "brute-force spectral "
      "integration (ΔE2000)";
  t.columns = {{"material"},
               {"class"},
               {"model"},
               {"parameters"},
               {"curve_rms_de00", 3},
               {"ibl"},
               {"ibl_rms_de00", 3},
               {"ibl_max_de00", 3},
               {"ibl_table_rms_de00", 3},
               {"ibl_nv_rms_de00", 3},
               {"ibl_hoffman_rms_de00", 3},
               {"ibl_basis_rms_de00", 3},
               {"area"},
               {"area_rms_de00", 3},
               {"area_max_de00", 3},
               {"area_table_rms_de00", 3},
               {"area_nv_rms_de00", 3},
               {"area_hoffman_rms_de00", 3},
               {"area_basis_rms_de00", 3}};
  std::vector<std::vector<RenderedCandidate>> per_material(studies.size());
  parallel_for(studies.size(),
               [&](size_t i) { per_material[i] = rendered_candidates(ctx, studies[i], points); });
  std::vector<std::vector<RenderedCandidate>> per_metal;
  for (size_t i = 0; i < studies.size(); ++i) {
    const auto& m = studies[i].material->material;
    if (m.material_class == spectral::MaterialClass::Metal) per_metal.push_back(per_material[i]);
    for (const auto& c : per_material[i])
      t.rows.push_back({m.name, std::string(spectral::to_string(m.material_class)),
                        std::string(fresnel::model_spec(c.model).name),
                        std::string(parameter_set_name(c.set)), c.punctual_rms,
                        approximation(c.model, Lighting::Ibl), c.ibl.rms, c.ibl.max,
                        c.ibl_table.rms, c.ibl_ways[0], c.ibl_ways[1], c.ibl_ways[2],
                        approximation(c.model, Lighting::Area), c.area.rms, c.area.max,
                        c.area_table.rms, c.area_ways[0], c.area_ways[1], c.area_ways[2]});
  }
  if (!per_metal.empty())
    t.reading = fmt::format(
        "With the spectral F0 and F82 (derived sets): {}; {}. The models no shared table holds, "
        "evaluated at n·v, render with the errors listed beside their curve errors. {} {}",
        f82_against_schlick(per_metal, Lighting::Ibl),
        f82_against_schlick(per_metal, Lighting::Area), rendered_gain(studies, per_material),
        projection_gain(studies, per_material));
  t.notes = accuracy_notes(ctx);
  return t;
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

}  // namespace fl::analysis
