#include "analysis/tables/lut_accuracy.h"

#include <fmt/format.h>

#include <algorithm>

#include "fresnel/projection.h"
#include "fresnel/registered_models.h"
#include "util/median.h"
#include "util/parallel.h"

namespace fl::analysis {

using fresnel::Model;

namespace {

std::vector<RenderedCandidate> candidates(const Context& ctx, const MaterialStudy& study,
                                          const std::vector<ShadingPoint>& points,
                                          const std::vector<color::Rgb>& truth) {
  std::vector<RenderedCandidate> out;
  for (const auto& r : study.models) {
    for (int fitted = 0; fitted < 2; ++fitted) {
      if (fitted && (!r.fitted.usable || r.fitted.parameters.empty())) continue;
      RenderedCandidate c;
      c.model = r.model;
      c.fitted = fitted != 0;
      c.params = fitted ? r.fitted.parameters : r.derived;
      c.punctual_rms = fitted ? r.fitted_error.rms : r.derived_error.rms;
      c.ibl = error_stats(rendered_de00(ctx, truth, r.model, c.params, Lighting::Ibl, points));
      c.area = error_stats(rendered_de00(ctx, truth, r.model, c.params, Lighting::Area, points));
      out.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace

std::vector<RenderedCandidate> rendered_candidates(const Context& ctx, const MaterialStudy& study,
                                                   const std::vector<ShadingPoint>& points) {
  return candidates(ctx, study, points, lobe_truth(ctx, *study.material, points));
}

namespace {

// A candidate's own curve (at the context's angles, as punctual lights show it) projected on a span
// of the tables' terms per channel, then rendered through the tables.
struct Projected {
  ErrorStats ibl_hoffman, area_hoffman, ibl_basis, area_basis;
};
std::array<fresnel::TableTerms, 3> projected_weights(const Context& ctx, const RenderedCandidate& c,
                                                     std::span<const fresnel::Term> span) {
  const auto& mu = ctx.cos_thetas();
  const auto curve = fresnel::evaluate_curve(c.model, c.params, mu);
  std::array<fresnel::TableTerms, 3> w;
  for (int ch = 0; ch < 3; ++ch) {
    std::vector<double> f;
    for (const auto& rgb : curve) f.push_back(rgb[ch]);
    w[ch] = fresnel::project_on_terms(mu, f, span);
  }
  return w;
}
Projected projected(const Context& ctx, const RenderedCandidate& c,
                    const std::vector<color::Rgb>& truth, const std::vector<ShadingPoint>& points) {
  const auto hoffman = projected_weights(ctx, c, fresnel::kHoffmanSpan);
  const auto basis = projected_weights(ctx, c, fresnel::kBasisSpan);
  auto stats = [&](const std::array<fresnel::TableTerms, 3>& w, Lighting l) {
    return error_stats(rendered_de00_terms(ctx, truth, w, l, points));
  };
  return {stats(hoffman, Lighting::Ibl), stats(hoffman, Lighting::Area),
          stats(basis, Lighting::Ibl), stats(basis, Lighting::Area)};
}

// A metal's candidates, each also projected on the Hoffman span and on the basis.
struct MetalRows {
  std::vector<RenderedCandidate> candidates;
  std::vector<Projected> projected;
};
MetalRows metal_rows(const Context& ctx, const MaterialStudy& study,
                     const std::vector<ShadingPoint>& points) {
  const auto truth = lobe_truth(ctx, *study.material, points);
  MetalRows r{candidates(ctx, study, points, truth), {}};
  for (const auto& c : r.candidates) r.projected.push_back(projected(ctx, c, truth, points));
  return r;
}

std::string approximation(Model m, Lighting l) {
  const auto& s = lighting_support(m, l);
  return s.fresnel_pre_integrated ? "tables" : fmt::format("F({}) × lobe", s.evaluated_at);
}

const RenderedCandidate* find(const std::vector<RenderedCandidate>& cs, Model m, bool fitted) {
  for (const auto& c : cs)
    if (c.model == m && c.fitted == fitted) return &c;
  return nullptr;
}

// "F82 ≤ Schlick for k of n metals" under one lighting, derived parameter sets (spectral F0, F82).
std::string f82_against_schlick(const std::vector<std::vector<RenderedCandidate>>& per_metal,
                                Lighting l) {
  int no_worse = 0;
  std::vector<double> schlick, f82;
  for (const auto& cs : per_metal) {
    const auto* s = find(cs, fresnel::model_of<fresnel::models::Schlick>, false);
    const auto* f = find(cs, fresnel::model_of<fresnel::models::F82>, false);
    no_worse += f->under(l).rms <= s->under(l).rms;
    schlick.push_back(s->under(l).rms);
    f82.push_back(f->under(l).rms);
  }
  return fmt::format(
      "under {}, pre-integrated F82 is no worse than pre-integrated Schlick for {} of {} metals "
      "(median RMS ΔE2000 {:.3f} against {:.3f})",
      lighting_name(l), no_worse, per_metal.size(), median(f82), median(schlick));
}

// The models no table holds (derived sets), three ways under one lighting: medians over metals and
// models of F(n·v) × lobe, the Hoffman projection and the basis projection.
std::string projections_summary(const std::vector<MetalRows>& rows, Lighting l) {
  std::vector<double> lobe, hoffman, basis;
  for (const auto& r : rows)
    for (size_t k = 0; k < r.candidates.size(); ++k) {
      const auto& c = r.candidates[k];
      if (c.fitted || lighting_support(c.model, l).fresnel_pre_integrated) continue;
      const auto& p = r.projected[k];
      lobe.push_back(c.under(l).rms);
      hoffman.push_back(l == Lighting::Ibl ? p.ibl_hoffman.rms : p.area_hoffman.rms);
      basis.push_back(l == Lighting::Ibl ? p.ibl_basis.rms : p.area_basis.rms);
    }
  if (lobe.empty()) return "";
  return fmt::format(
      " Under {}, the models no table holds (derived sets) render at a median RMS ΔE2000 of {:.3f} "
      "as F(n·v) × lobe, {:.3f} projected on Hoffman's span and {:.3f} projected on the basis.",
      lighting_name(l), median(lobe), median(hoffman), median(basis));
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
                  "tabulated at {} "
                  "values of cos θ, linear interpolation).",
                  kTruthCurveSize),
      fmt::format(
          "Engine: the {0}² tables as `lut` writes them, read bilinearly (DFG at (n·v, roughness) "
          "on texel "
          "centres; LTC moments at (roughness, √(1 − n·v)) on endpoints). `tables`: the Fresnel "
          "term is "
          "pre-integrated, a·n + b·f + c·l with F = a + b(1 − μ)⁵ + cμ(1 − μ)⁶ (Schlick: F0·dfg1 + "
          "dfg2; "
          "F82: … − a·dfg_f82, unclamped); `F(n·v) × lobe`: the model at n·v times the lobe's "
          "Fresnel-free "
          "integral (dfg1 + dfg2, n_D), the stated approximation for models no shared table holds.",
          kEngineLutSize),
      "hoffman and basis5: the model's own curve (at the working angles, as punctual lights show "
      "it) projected per channel by least squares on Hoffman's span {1, (1 − μ)⁵, μ(1 − μ)⁶} or "
      "on the 5-term Fresnel basis {1, (1 − μ)⁵, b2, b3, b4}, then rendered through the tables: "
      "any model pre-integrated.",
      "curve_rms_de00: the curve's RMS ΔE2000 over the angles, what punctual lights render. rms "
      "and max: over the "
      "shading points. The lobe's shape (LTC matrix, prefiltered environment) is the same for "
      "every model and not "
      "part of these errors.",
      "Only metals are listed."};
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
               {"model"},
               {"parameters"},
               {"curve_rms_de00", 3},
               {"ibl"},
               {"ibl_rms_de00", 3},
               {"ibl_max_de00", 3},
               {"area"},
               {"area_rms_de00", 3},
               {"area_max_de00", 3},
               {"ibl_hoffman_rms_de00", 3},
               {"area_hoffman_rms_de00", 3},
               {"ibl_basis5_rms_de00", 3},
               {"area_basis5_rms_de00", 3}};
  std::vector<const MaterialStudy*> metals;
  for (const auto& s : studies)
    if (s.material->material.material_class == spectral::MaterialClass::Metal) metals.push_back(&s);
  std::vector<MetalRows> rows(metals.size());
  parallel_for(metals.size(), [&](size_t i) { rows[i] = metal_rows(ctx, *metals[i], points); });
  std::vector<std::vector<RenderedCandidate>> per_metal;
  for (size_t i = 0; i < metals.size(); ++i) {
    per_metal.push_back(rows[i].candidates);
    for (size_t k = 0; k < rows[i].candidates.size(); ++k) {
      const auto& c = rows[i].candidates[k];
      const auto& p = rows[i].projected[k];
      t.rows.push_back({metals[i]->material->material.name,
                        std::string(fresnel::model_spec(c.model).name),
                        std::string(c.fitted ? "fitted" : "derived"), c.punctual_rms,
                        approximation(c.model, Lighting::Ibl), c.ibl.rms, c.ibl.max,
                        approximation(c.model, Lighting::Area), c.area.rms, c.area.max,
                        p.ibl_hoffman.rms, p.area_hoffman.rms, p.ibl_basis.rms, p.area_basis.rms});
    }
  }
  if (!per_metal.empty())
    t.reading = fmt::format(
        "With the spectral F0 and F82 (derived sets): {}; {}. The models no shared table holds, "
        "evaluated at n·v, render with the errors listed beside their curve errors.{}{}",
        f82_against_schlick(per_metal, Lighting::Ibl),
        f82_against_schlick(per_metal, Lighting::Area), projections_summary(rows, Lighting::Ibl),
        projections_summary(rows, Lighting::Area));
  t.notes = accuracy_notes(ctx);
  return t;
}

}  // namespace fl::analysis
