#include "analysis/lut/rendered.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "color/lab.h"
#include "fresnel/ground_truth.h"
#include "fresnel/projection.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::analysis {

using fresnel::Model;

const char* lighting_name(Lighting l) {
  switch (l) {
    case Lighting::Punctual:
      return "punctual";
    case Lighting::Ibl:
      return "ibl";
    case Lighting::Area:
      return "area";
  }
  return "?";
}

Lighting lighting_from_name(const std::string& name) {
  std::vector<NameChoice> choices;
  for (Lighting l : {Lighting::Punctual, Lighting::Ibl, Lighting::Area})
    choices.push_back({lighting_name(l), {}});
  choices[1].aliases = {"dfg", "split-sum"};
  choices[2].aliases = {"ltc"};
  if (const auto match = match_name(name, choices))
    for (Lighting l : {Lighting::Punctual, Lighting::Ibl, Lighting::Area})
      if (*match == lighting_name(l)) return l;
  throw InputError(unknown_name_message("lighting", name, choices));
}

const fresnel::LightingSupport& lighting_support(Model m, Lighting l) {
  const auto& pi = fresnel::model_spec(m).pre_integration;
  return l == Lighting::Ibl ? pi.ibl : l == Lighting::Area ? pi.area : pi.punctual;
}

std::vector<color::Rgb> lobe_truth(const Context& ctx, const LoadedMaterial& m,
                                   const std::vector<ShadingPoint>& points) {
  const double eta_e = ctx.settings().eta_outside;
  const auto& mu = truth_nodes();
  std::array<color::Rgb, kTruthNodes> curve{};
  std::array<bool, kTruthNodes> needed{};
  for (const auto& p : points)
    for (size_t k = 0; k < p.truth_weights.size(); ++k)
      needed[k] = needed[k] || p.truth_weights[k] != 0.0;
  std::array<double, kTruthNodes> at{};
  std::array<int, kTruthNodes> node{};
  size_t count = 0;
  for (int k = 0; k < kTruthNodes; ++k)
    if (needed[k]) at[count] = mu[k], node[count++] = k;
  std::array<color::Rgb, kTruthNodes> at_curve;
  fresnel::spectral_reflectance_rgb(ctx.rgb_weights(), m.ior, std::span(at.data(), count), eta_e,
                                    at_curve.data());
  for (size_t j = 0; j < count; ++j) curve[node[j]] = at_curve[j];
  std::vector<color::Rgb> out;
  for (const auto& p : points) {
    if (p.mirror) {
      out.push_back(ground_truth_rgb(ctx, m.ior, p.nov, eta_e));
      continue;
    }
    color::Rgb sum{};
    for (int k = 0; k < kTruthNodes; ++k)
      if (p.truth_weights[k] != 0.0) sum = sum + p.truth_weights[k] * curve[k];
    out.push_back(sum);
  }
  return out;
}

namespace {

// The lobe's integral of each of the tables' terms at a point (the norm is the term 1's); a
// mirror's lobe is its one direction.
fresnel::TermValues lobe_integrals(bool ibl, const ShadingPoint& p, Integrals integrals) {
  if (p.mirror) {  // the lobe is the one direction v·h = n·v: each term at n·v
    fresnel::TermValues at_nov;
    const double m = 1.0 - p.nov, m5 = m * m * m * m * m;
    for (const auto& t : fresnel::kTermRegistry) at_nov[t.term] = t.kernel(p.nov, m, m5);
    return at_nov;
  }
  const bool exact = integrals == Integrals::Exact;
  if (ibl) return fresnel::dfg_term_integrals(exact ? p.dfg_exact : p.dfg);
  return exact ? p.ltc_exact : p.ltc;
}

// F(n·v) × the lobe's Fresnel-free integral: how an engine shades a model no table holds.
color::Rgb shading_at_nov(Model m, const std::vector<double>& params, Lighting lighting,
                          const ShadingPoint& p, Integrals integrals = Integrals::Tables) {
  return lobe_integrals(lighting == Lighting::Ibl, p, integrals)[fresnel::Term::One] *
         fresnel::model_spec(m).evaluate(p.nov, params.data(), false);
}

}  // namespace

color::Rgb engine_shading_terms(const std::array<fresnel::TableTerms, 3>& weights,
                                Lighting lighting, const ShadingPoint& p, Integrals integrals) {
  if (lighting == Lighting::Punctual) throw std::logic_error("punctual lights integrate no lobe");
  const auto lobe = lobe_integrals(lighting == Lighting::Ibl, p, integrals);
  color::Rgb out{};
  for (int c = 0; c < 3; ++c) {
    const auto& w = weights[c];
    out[c] = w.v[0] * lobe.v[0];
    for (size_t t = 1; t < fresnel::kTermCount; ++t) out[c] += w.v[t] * lobe.v[t];
  }
  return out;
}

namespace {

// What the engine computes at p for a model whose table-term weights per channel are `w` (used
// where the lighting pre-integrates it).
color::Rgb shade(const fresnel::ModelSpec& spec, Model m, const std::vector<double>& params,
                 bool pre_integrated, const std::array<fresnel::TableTerms, 3>& w,
                 Lighting lighting, const ShadingPoint& p, Integrals integrals) {
  if (p.mirror) return spec.evaluate(p.nov, params.data(), false);  // no table: F(n·v)
  if (!pre_integrated) return shading_at_nov(m, params, lighting, p, integrals);
  return engine_shading_terms(w, lighting, p, integrals);
}

std::array<fresnel::TableTerms, 3> model_table_terms(const fresnel::ModelSpec& spec,
                                                     const std::vector<double>& params) {
  std::array<fresnel::TableTerms, 3> w;
  for (int c = 0; c < 3; ++c) w[c] = spec.table_terms(params.data(), c);
  return w;
}

}  // namespace

color::Rgb engine_shading(Model m, const std::vector<double>& params, Lighting lighting,
                          const ShadingPoint& p, Integrals integrals) {
  color::Rgb out;
  engine_shading(m, params, lighting, std::span(&p, 1), &out, integrals);
  return out;
}

void engine_shading(Model m, const std::vector<double>& params, Lighting lighting,
                    std::span<const ShadingPoint> points, color::Rgb* out, Integrals integrals) {
  if (lighting == Lighting::Punctual) throw std::logic_error("punctual lights integrate no lobe");
  const auto& spec = fresnel::model_spec(m);
  const bool pre = lighting_support(m, lighting).fresnel_pre_integrated;
  const auto w = pre ? model_table_terms(spec, params) : std::array<fresnel::TableTerms, 3>{};
  for (const auto& p : points) *out++ = shade(spec, m, params, pre, w, lighting, p, integrals);
}

std::vector<double> table_de00(const Context& ctx, Model m, const std::vector<double>& params,
                               Lighting lighting, const std::vector<ShadingPoint>& points) {
  std::vector<color::Rgb> exact(points.size()), tables(points.size());
  engine_shading(m, params, lighting, points, exact.data(), Integrals::Exact);
  engine_shading(m, params, lighting, points, tables.data());
  return de2000_per_angle(ctx, exact, tables);
}

std::vector<double> rendered_de00_terms(const Context& ctx,
                                        const std::vector<color::Lab>& truth_lab,
                                        const std::array<fresnel::TableTerms, 3>& weights,
                                        Lighting lighting,
                                        const std::vector<ShadingPoint>& points) {
  std::vector<color::Rgb> engine(points.size());
  for (size_t k = 0; k < points.size(); ++k)
    engine[k] = engine_shading_terms(weights, lighting, points[k]);
  return de2000_per_angle(ctx, truth_lab, engine);
}

std::vector<double> rendered_de00_terms(const Context& ctx, const std::vector<color::Rgb>& truth,
                                        const std::array<fresnel::TableTerms, 3>& weights,
                                        Lighting lighting,
                                        const std::vector<ShadingPoint>& points) {
  return rendered_de00_terms(ctx, lab_curve(ctx, truth), weights, lighting, points);
}

std::span<const fresnel::Term> projected_span(EngineWay w) {
  if (w == EngineWay::HoffmanSpan) return fresnel::kHoffmanSpan;
  if (w == EngineWay::BasisSpan) return fresnel::kBasisSpan;
  return {};
}

std::array<fresnel::TableTerms, 3> projected_weights(const Context& ctx, Model m,
                                                     const std::vector<double>& params,
                                                     std::span<const fresnel::Term> terms) {
  const auto& mu = ctx.cos_thetas();
  const auto curve = fresnel::evaluate_curve(m, params, mu);
  std::array<fresnel::TableTerms, 3> w;
  std::vector<double> f(mu.size());
  for (int c = 0; c < 3; ++c) {
    for (size_t j = 0; j < mu.size(); ++j) f[j] = curve[j][c];
    w[c] = fresnel::project_on_terms(mu, f, terms);
  }
  return w;
}

std::vector<double> rendered_de00(const Context& ctx, const std::vector<color::Lab>& truth_lab,
                                  Model m, const std::vector<double>& params, Lighting lighting,
                                  const std::vector<ShadingPoint>& points, EngineWay way) {
  if (!projected_span(way).empty())
    return rendered_de00_terms(
        ctx, truth_lab, projected_weights(ctx, m, params, projected_span(way)), lighting, points);
  std::vector<color::Rgb> engine(points.size());
  if (way == EngineWay::AtNdotV)
    for (size_t k = 0; k < points.size(); ++k)
      engine[k] = shading_at_nov(m, params, lighting, points[k]);
  else
    engine_shading(m, params, lighting, points, engine.data());
  return de2000_per_angle(ctx, truth_lab, engine);
}

std::vector<double> rendered_de00(const Context& ctx, const std::vector<color::Rgb>& truth, Model m,
                                  const std::vector<double>& params, Lighting lighting,
                                  const std::vector<ShadingPoint>& points, EngineWay way) {
  return rendered_de00(ctx, lab_curve(ctx, truth), m, params, lighting, points, way);
}

ErrorStats error_stats(const std::vector<double>& de00) {
  ErrorStats s;
  double sum2 = 0;
  for (double d : de00) {
    sum2 += d * d;
    s.max = std::max(s.max, d);
  }
  s.rms = de00.empty() ? 0.0 : std::sqrt(sum2 / static_cast<double>(de00.size()));
  return s;
}

}  // namespace fl::analysis
