#pragma once
// The lookup tables' accuracy as rendered: every Fresnel model as an engine shades it under
// image-based lighting (split-sum DFG table) and LTC area lights (the moments), against brute-force
// spectral integration of the GGX lobe (analysis/lut/rendered.h).
#include <vector>

#include "analysis/lut/rendered.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// One (model, parameter set) of a material with its errors: the curve's RMS ΔE2000 (what punctual
// lights render) and the rendered ΔE2000 over the shading points under each pre-integrated
// lighting.
struct RenderedCandidate {
  fresnel::Model model{};
  ParameterSet set = ParameterSet::Derived;
  std::vector<double> params;
  double punctual_rms = 0;
  ErrorStats ibl, area;  // as the model's own shader renders it (EngineWay::Native)
  // The tables' own share: the same shading from the tables against from the exact integrals.
  ErrorStats ibl_table, area_table;
  // RMS ΔE2000 under ibl and area the three ways any model can be rendered, in kProjectedWays
  // order: at n·v, projected on Hoffman's span, projected on the basis.
  std::array<double, 3> ibl_ways{}, area_ways{};
  const ErrorStats& under(Lighting l) const { return l == Lighting::Ibl ? ibl : area; }
  double rms_under(Lighting l) const {
    return l == Lighting::Punctual ? punctual_rms : under(l).rms;
  }
};
inline constexpr std::array<EngineWay, 3> kProjectedWays{EngineWay::AtNdotV, EngineWay::HoffmanSpan,
                                                         EngineWay::BasisSpan};
// Every model's derived set, its fitted set where the fit is usable, and its set fitted to the
// render at `points` (fit_rendered from the other two), in registry order.
std::vector<RenderedCandidate> rendered_candidates(const Context& ctx, const MaterialStudy& study,
                                                   const std::vector<ShadingPoint>& points);
// ModelResult::rendered of every studied model (of `models` only, when not empty): fit_rendered at
// `points`, starting from the derived and curve-fitted sets.
void add_rendered_fits(const Context& ctx, MaterialStudy& study,
                       const std::vector<ShadingPoint>& points,
                       const std::vector<fresnel::Model>& models = {});

// The shading points lut-accuracy renders: the default roughness set × the view angles.
std::vector<ShadingPoint> lut_accuracy_points();
// `table lut-accuracy`: per material, every model × {derived, fitted, rendered} under ibl and area,
// at lut_accuracy_points().
Table lut_accuracy_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                         const std::vector<ShadingPoint>& points);

// The study of one material with the parameter set `kind` names (parameter_set_from_name): curve
// fits for "fitted" and "rendered", and then only of `models` (empty: every model); rendered fits
// (add_rendered_fits at lut_accuracy_points) for "rendered". `one` holds the material and must
// outlive the study, which points into it.
MaterialStudy study_one(const Context& ctx, const std::vector<LoadedMaterial>& one,
                        const std::string& kind, const std::vector<fresnel::Model>& models = {});
// A model's derived, fitted or rendered parameters (`kind`) from a study.
const std::vector<double>& model_params(const MaterialStudy& st, fresnel::Model m,
                                        const std::string& kind);

}  // namespace fl::analysis
