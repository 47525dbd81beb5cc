#pragma once
// The registry's models seen through their handles: specs, names, and generic evaluation,
// derivation, fit starts and domain checks over the flat parameter layout (model_spec.h).
#include <string>
#include <vector>

#include "color/values.h"
#include "fresnel/derive.h"
#include "fresnel/model_spec.h"

namespace fl::fresnel {

const std::vector<ModelSpec>& model_specs();  // registry order
const ModelSpec& model_spec(Model m);
const ModelSpec& model_from_name(const std::string& name);  // InputError if unknown
// "schlick, generalized_schlick, ...": every model's name in registry order, for option help.
std::string model_names();

std::vector<color::Rgb> evaluate_curve(Model m, const std::vector<double>& params,
                                       const std::vector<double>& cos_thetas);

// As evaluate_curve, but without the kernel's output clamp where it has one (the F82 model's
// [0, 1]): the formula itself, linear in its parameters, for comparisons of linearity.
std::vector<color::Rgb> evaluate_curve_unclamped(Model m, const std::vector<double>& params,
                                                 const std::vector<double>& cos_thetas);

// The kernel's output clamp changed the curve somewhere (false for models without one).
bool output_clamped(Model m, const std::vector<double>& params,
                    const std::vector<double>& cos_thetas);

// How many reflectance parameters (F0, F82, F90) lie outside [0, 1].
int reflectances_outside_unit(Model m, const std::vector<double>& params);

// Moves parameters into the model's domain (ParamSpec::domain). Returns how many moved.
int clamp_to_domain(Model m, std::vector<double>& params);

// The model's "derived" parameter set from the material's spectral data (DeriveInput), and its fit
// starts: the derived set first, then the unit's other derivations (deterministic).
std::vector<double> derived_model_params(Model m, const DeriveInput& in);
std::vector<std::vector<double>> fit_starts(Model m, const DeriveInput& in);

// Plausible parameters (gold in ACEScg, roughly) for benchmarks and examples.
std::vector<double> example_params(Model m);

}  // namespace fl::fresnel
