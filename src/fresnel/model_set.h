#pragma once
// Every Fresnel model Fresnel Lab compares, with a flat parameter layout shared by evaluation,
// derivation, fitting and reports: per-channel parameters first (R block, G block, B block),
// then parameters shared by the channels.
#include <string>
#include <vector>

#include "color/types.h"
#include "fresnel/models.h"

namespace fl::fresnel {

enum class Model { Schlick, GeneralizedSchlick, CookTorrance, Lazanyi, F82, Gulbrandsen, FresnelRgb };

struct ParamRange {
  double lo, hi;
};

struct ModelSpec {
  Model model;
  const char* name;   // command-line / CSV name
  const char* label;  // for people
  std::vector<std::string> channel_params;  // per channel
  std::vector<std::string> shared_params;
  std::vector<ParamRange> channel_bounds;   // fit bounds, per channel parameter
  std::vector<ParamRange> shared_bounds;
  // The model can leave [0, 1] for some parameters (reported, not clamped).
  bool can_leave_unit_range;

  int per_channel() const { return static_cast<int>(channel_params.size()); }
  int param_count() const { return 3 * per_channel() + static_cast<int>(shared_params.size()); }
  std::vector<std::string> param_names() const;  // "f0_r", ..., "eta_rep"
  std::vector<ParamRange> bounds() const;
};

const std::vector<ModelSpec>& model_specs();
const ModelSpec& model_spec(Model m);
const ModelSpec& model_from_name(const std::string& name);  // InputError if unknown

// One channel: `p` are that channel's parameters, `shared` the shared ones.
template <class T>
T evaluate_channel(Model m, T cos_theta, const T* p, const T* shared) {
  switch (m) {
    case Model::Schlick: return schlick(cos_theta, p[0]);
    case Model::GeneralizedSchlick: return generalized_schlick(cos_theta, p[0], p[1], p[2]);
    case Model::CookTorrance: return cook_torrance(cos_theta, p[0], shared[0], shared[1]);
    case Model::Lazanyi: return lazanyi(cos_theta, p[0], p[1], p[2]);
    case Model::F82: return hoffman_f82(cos_theta, p[0], p[1]);
    case Model::Gulbrandsen: return gulbrandsen(cos_theta, p[0], p[1]);
    case Model::FresnelRgb: return fresnel_conductor(cos_theta, p[0], p[1]);
  }
  return T(0.0);
}

// All three channels from the flat parameter vector.
template <class T>
color::RgbT<T> evaluate_rgb(Model m, int per_channel, T cos_theta, const T* params) {
  const T* shared = params + 3 * per_channel;
  return {evaluate_channel(m, cos_theta, params, shared),
          evaluate_channel(m, cos_theta, params + per_channel, shared),
          evaluate_channel(m, cos_theta, params + 2 * per_channel, shared)};
}

std::vector<color::Rgb> evaluate_curve(Model m, const std::vector<double>& params,
                                       const std::vector<double>& cos_thetas);

// As evaluate_curve, but the F82 model without its [0, 1] output clamp: the formula itself, linear
// in (F0, F82), for comparisons of linearity (blending, gamut conversion).
std::vector<color::Rgb> evaluate_curve_unclamped(Model m, const std::vector<double>& params,
                                                 const std::vector<double>& cos_thetas);

// How many reflectance parameters (F0, F82, F90) lie outside [0, 1].
int reflectances_outside_unit(Model m, const std::vector<double>& params);

// Moves parameters into the model's domain, where a model has one: Gulbrandsen F0 ∈ [0, 0.99999]
// and g ∈ [0, 1]; RGB Fresnel η ≥ 0.01, κ ≥ 0; exponents (p, α) ≥ 0.01. Schlick, the F82 model and
// Cook-Torrance's F0 are defined for any value (they stay linear). Returns how many moved.
int clamp_to_domain(Model m, std::vector<double>& params);

// The F82 model's result before clamping leaves [0, 1] somewhere on the curve.
bool f82_model_clamps(const std::vector<double>& params, const std::vector<double>& cos_thetas);

}  // namespace fl::fresnel
