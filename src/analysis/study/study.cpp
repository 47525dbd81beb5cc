#include "analysis/study/study.h"

#include <algorithm>

#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/suggest.h"

namespace fl::analysis {

using fresnel::Model;

const ModelResult& MaterialStudy::result(Model m) const {
  for (const auto& r : models)
    if (r.model == m) return r;
  throw std::logic_error("model not studied");
}

const char* parameter_set_name(ParameterSet s) {
  switch (s) {
    case ParameterSet::Derived:
      return "derived";
    case ParameterSet::Fitted:
      return "fitted";
    case ParameterSet::Rendered:
      return "rendered";
  }
  return "";
}

ParameterSet parameter_set_from_name(const std::string& name) {
  std::vector<NameChoice> choices;
  for (const auto s : {ParameterSet::Derived, ParameterSet::Fitted, ParameterSet::Rendered})
    choices.push_back({parameter_set_name(s), {}});
  if (const auto match = match_name(name, choices))
    for (const auto s : {ParameterSet::Derived, ParameterSet::Fitted, ParameterSet::Rendered})
      if (*match == parameter_set_name(s)) return s;
  throw InputError(unknown_name_message("parameter set", name, choices));
}

fit::CurveTarget curve_target(const Context& ctx, const std::vector<color::Rgb>& truth) {
  fit::CurveTarget t;
  t.cos_thetas = ctx.cos_thetas();
  t.to_lab = {ctx.space().rgb_to_xyz, ctx.space().white};
  t.truth_lab = lab_curve(ctx, truth);
  return t;
}

bool is_lossless(const spectral::ComplexIorSpectrum& ior) {
  for (const auto& z : ior.ior)
    if (z.imag() > fit::kLosslessMaxK) return false;
  return true;
}

namespace {

MaterialStudy study_one(const Context& ctx, const LoadedMaterial& m, const StudyOptions& o) {
  MaterialStudy st;
  st.material = &m;
  const double eta_e = ctx.settings().eta_outside;
  st.truth = ground_truth_curve(ctx, m.ior, eta_e);
  st.derived = fresnel::derive_parameters(ctx.rgb_weights(), ctx.space().rgb_to_xyz, m.ior, eta_e,
                                          o.point_sample_nm);
  const auto& d = st.derived;
  const auto& cos = ctx.cos_thetas();
  const fresnel::DeriveInput in{d, m.ior, eta_e, ctx.rgb_weights(), cos, st.truth};
  // The truth in CIELAB once, for the fits and for every curve measured against it.
  const auto target = curve_target(ctx, st.truth);
  const auto& truth_lab = target.truth_lab;
  fit::FitOptions fit_options;
  fit_options.lossless = st.lossless = is_lossless(m.ior);
  fit_options.function_tolerance = o.fit_tolerance;
  // One slot per model, in registry order: the fits of a material run in parallel.
  std::vector<const fresnel::ModelSpec*> specs;
  for (const auto& spec : fresnel::model_specs())
    if (o.studies(spec.model)) specs.push_back(&spec);
  st.models.resize(specs.size());
  parallel_for(
      specs.size(),
      [&](size_t k) {
        const auto& spec = *specs[k];
        ModelResult& r = st.models[k];
        r.model = spec.model;
        r.derived = fresnel::derived_model_params(spec.model, in);
        if (o.derived_errors) {
          r.derived_error =
              curve_error(ctx, truth_lab, fresnel::evaluate_curve(spec.model, r.derived, cos));
          r.derived_clamps = fresnel::output_clamped(spec.model, r.derived, cos);
        }
        if (o.fits(spec.model)) {
          r.fitted =
              fit::fit_model(spec.model, target, fresnel::fit_starts(spec.model, in), fit_options);
          r.fitted_error = curve_error(
              ctx, truth_lab, fresnel::evaluate_curve(spec.model, r.fitted.parameters, cos));
          r.fitted_clamps = fresnel::output_clamped(spec.model, r.fitted.parameters, cos);
        }
      },
      o.threads);
  if (!o.method_errors) return st;
  std::vector<double> ps;
  for (int c = 0; c < 3; ++c) ps.insert(ps.end(), {d.eta_ps[c], d.kappa_ps[c]});
  st.ps_eta_kappa =
      curve_error(ctx, truth_lab,
                  fresnel::evaluate_curve(fresnel::model_of<fresnel::models::FresnelRgb>, ps, cos));
  const auto g_ps = fresnel::gulbrandsen_params(d.f0, d.g_ps_eta, &st.g_clamped_ps);
  fresnel::gulbrandsen_params(d.f0, d.g_refl_eta, &st.g_clamped_refl);
  st.refl_f0_ps_eta = curve_error(
      ctx, truth_lab,
      fresnel::evaluate_curve(fresnel::model_of<fresnel::models::Gulbrandsen>, g_ps, cos));
  return st;
}

}  // namespace

std::vector<MaterialStudy> study_materials(const Context& ctx,
                                           const std::vector<LoadedMaterial>& materials,
                                           const StudyOptions& options,
                                           const std::function<void(int, int)>& progress) {
  std::vector<MaterialStudy> out(materials.size());
  ProgressCounter done(progress, static_cast<int>(materials.size()));
  parallel_for(
      materials.size(),
      [&](size_t i) {
        out[i] = study_one(ctx, materials[i], options);
        done.add(1);
      },
      options.threads);
  return out;
}

std::vector<color::Rgb> schlick_curve(const Context& ctx, const color::Rgb& f0) {
  return fresnel::evaluate_curve(fresnel::model_of<fresnel::models::Schlick>, {f0.r, f0.g, f0.b},
                                 ctx.cos_thetas());
}

}  // namespace fl::analysis
