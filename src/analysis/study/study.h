#pragma once
// Everything the parameter tables need per material, computed once: ground truth, derived
// parameters, and every model's derived and fitted parameter sets with their errors.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "analysis/pipeline/context.h"
#include "fit/fit.h"
#include "fresnel/derive.h"

namespace fl::analysis {

// A model's parameter sets: derived by the spectral procedure, fitted to the curve (Ceres), or
// fitted to the rendered result under IBL and area lights (analysis/lut/rendered_fit.h).
enum class ParameterSet { Derived, Fitted, Rendered };
const char* parameter_set_name(ParameterSet s);  // derived | fitted | rendered
// InputError naming the choices (and the closest) for anything else.
ParameterSet parameter_set_from_name(const std::string& name);

struct ModelResult {
  fresnel::Model model;
  std::vector<double> derived;
  CurveError derived_error;
  fit::FitResult fitted;
  CurveError fitted_error;
  fit::FitResult rendered;  // empty unless asked for (add_rendered_fits)
  bool derived_clamps = false,
       fitted_clamps = false;  // the kernel's output clamp changed the curve
};

struct MaterialStudy {
  const LoadedMaterial* material = nullptr;
  std::vector<color::Rgb> truth;
  fresnel::DerivedParameters derived;
  std::vector<ModelResult> models;  // registry order
  // The talk's method table (docs/conventions.md) beyond what `models` holds.
  CurveError ps_eta_kappa, refl_f0_ps_eta;
  int g_clamped_ps = 0, g_clamped_refl = 0;  // channels whose g left [0, 1]
  bool lossless = false;  // k ≤ fit::kLosslessMaxK over the grid: fits hold κ at 0

  const ModelResult& result(fresnel::Model m) const;
  bool is_metal() const {
    return material->material.material_class == spectral::MaterialClass::Metal;
  }
};

struct StudyOptions {
  std::array<double, 3> point_sample_nm = fresnel::kDefaultPointSampleNm;
  bool fit = true;  // run the Ceres fits (fitted parameter sets)
  // With `fit`: the models to fit (empty: every model); the others' fitted results stay empty.
  std::vector<fresnel::Model> fitted_models;
  // The models studied (empty: every model), in registry order; MaterialStudy::result throws for
  // the others.
  std::vector<fresnel::Model> models;
  // The derived sets' curve errors and output clamps (ModelResult::derived_error,
  // derived_clamps); off, they stay empty (a caller that reads the parameters alone).
  bool derived_errors = true;
  // The talk's method table's extra errors (MaterialStudy::ps_eta_kappa, refl_f0_ps_eta).
  bool method_errors = true;
  // The curve fits stop once a step lowers the cost by less than this share of it
  // (fit::FitOptions::function_tolerance).
  double fit_tolerance = fit::FitOptions{}.function_tolerance;
  int threads = 0;  // 0: hardware concurrency

  bool studies(fresnel::Model m) const {
    return models.empty() || std::find(models.begin(), models.end(), m) != models.end();
  }

  bool fits(fresnel::Model m) const {
    return fit && (fitted_models.empty() ||
                   std::find(fitted_models.begin(), fitted_models.end(), m) != fitted_models.end());
  }
};

// Studies every material (in parallel over materials; each study is deterministic).
// `progress` is called after each material with (done, total).
std::vector<MaterialStudy> study_materials(const Context& ctx,
                                           const std::vector<LoadedMaterial>& materials,
                                           const StudyOptions& options,
                                           const std::function<void(int, int)>& progress = {});

// k at most fit::kLosslessMaxK at every grid wavelength.
bool is_lossless(const spectral::ComplexIorSpectrum& ior);

// The target of a fit: the ground truth in the working space's CIELAB at the context's angles.
fit::CurveTarget curve_target(const Context& ctx, const std::vector<color::Rgb>& truth);

// Schlick's curve of `f0` at the context's angles.
std::vector<color::Rgb> schlick_curve(const Context& ctx, const color::Rgb& f0);

}  // namespace fl::analysis
