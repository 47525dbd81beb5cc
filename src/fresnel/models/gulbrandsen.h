#pragma once
// Gulbrandsen's artist-friendly metallic Fresnel: F0 (reflectivity r) and edge tint g per channel.
#include <algorithm>
#include <array>
#include <vector>

#include "color/autodiff.h"
#include "fresnel/derive.h"
#include "fresnel/exact.h"
#include "fresnel/exact_shader.h"
#include "fresnel/model_spec.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

// Gulbrandsen 2014, "Artist Friendly Metallic Fresnel": (r, g) → η, κ, then the exact conductor
// equations. r is clamped below 1 (the mapping is singular at r = 1) and above 0.
constexpr double kGulbrandsenMaxR = 0.99999;
template <class T>
T gulbrandsen_clamp_r(T r) {
  if (r > T(kGulbrandsenMaxR)) return T(kGulbrandsenMaxR);
  if (r < T(1e-9)) return T(1e-9);
  return r;
}
template <class T>
T gulbrandsen_n_min(T r) {
  return (T(1.0) - r) / (T(1.0) + r);
}
template <class T>
T gulbrandsen_n_max(T r) {
  using std::sqrt;
  const T s = sqrt(r);
  return (T(1.0) + s) / (T(1.0) - s);
}
template <class T>
T gulbrandsen_eta(T r, T g) {
  r = gulbrandsen_clamp_r(r);
  return g * gulbrandsen_n_min(r) + (T(1.0) - g) * gulbrandsen_n_max(r);
}
template <class T>
T gulbrandsen_kappa(T r, T eta) {
  r = gulbrandsen_clamp_r(r);
  const T num = r * (eta + T(1.0)) * (eta + T(1.0)) - (eta - T(1.0)) * (eta - T(1.0));
  return color::safe_sqrt(num / (T(1.0) - r));
}
// Gulbrandsen 2014, inverted: the edge tint g that gives index eta at reflectance r (η is linear
// in g between n_max at g = 0 and n_min at g = 1).
template <class T>
T gulbrandsen_g(T r, T eta) {
  r = gulbrandsen_clamp_r(r);
  const T n_min = gulbrandsen_n_min(r), n_max = gulbrandsen_n_max(r);
  return (n_max - eta) / (n_max - n_min);
}
// A channel's (F0, g) as the index they stand for: the part of Gulbrandsen's Fresnel that does not
// depend on the angle.
template <class T>
struct GulbrandsenIndex {
  T eta, kappa;
};
template <class T>
GulbrandsenIndex<T> gulbrandsen_index(T f0, T g) {
  const T eta = gulbrandsen_eta(f0, g);
  return {eta, gulbrandsen_kappa(f0, eta)};
}
template <class T>
T gulbrandsen_at(T cos_theta, const GulbrandsenIndex<T>& index) {
  return fresnel_conductor(cos_theta, index.eta, index.kappa);
}
template <class T>
T gulbrandsen(T cos_theta, T f0, T g) {
  return gulbrandsen_at(cos_theta, gulbrandsen_index(f0, g));
}

// Gulbrandsen parameters (F0, g) with g clamped to [0, 1]; `clamped` counts channels moved.
inline std::vector<double> gulbrandsen_params(const color::Rgb& f0, const color::Rgb& g,
                                              int* clamped = nullptr) {
  std::vector<double> p;
  for (int c = 0; c < 3; ++c) {
    const double gc = std::clamp(g[c], 0.0, 1.0);
    if (clamped && gc != g[c]) ++*clamped;
    p.push_back(f0[c]);
    p.push_back(gc);
  }
  return p;
}

namespace models {

struct Gulbrandsen {
  static constexpr const char* kName = "gulbrandsen";
  static constexpr const char* kLabel = "Gulbrandsen 2014 (F0, g)";
  static constexpr std::array<ParamSpec, 2> kChannelParams{{
      {"f0",
       "reflectance",
       ParamKind::Reflectance,
       {0.0, kGulbrandsenMaxR},
       {0.0, kGulbrandsenMaxR}},
      {"g", "edge tint", ParamKind::Coefficient, {0.0, 1.0}, {0.0, 1.0}},
  }};
  static constexpr std::array<ParamSpec, 0> kSharedParams{};
  static constexpr bool kCanLeaveUnitRange = false;
  static constexpr UnitFeatures kFeatures{.prepared_channel = true, .identifiable = true};
  // No table terms: exact conductor equations of a per-channel index.
  static constexpr ShaderCode kShader{kConductorHelpers, R"(  vec3 r = clamp(f0, 1e-9, 0.99999);
  vec3 s = sqrt(r);
  vec3 eta = g * (1.0 - r) / (1.0 + r) + (1.0 - g) * (1.0 + s) / (1.0 - s);
  vec3 k2 = (r * (eta + 1.0) * (eta + 1.0) - (eta - 1.0) * (eta - 1.0)) / (1.0 - r);
  return fl_fresnel_conductor(cos_theta, eta, sqrt(max(k2, 0.0)));
)"};

  template <class T>
  static T channel(T cos_theta, const T* p, const T*) {
    return gulbrandsen(cos_theta, p[0], p[1]);
  }
  // The channel split at the angle (prepare_channel, model_spec.h).
  template <class T>
  static GulbrandsenIndex<T> prepare(const T* p, const T*) {
    return gulbrandsen_index(p[0], p[1]);
  }
  template <class T>
  static T channel_at(T cos_theta, const GulbrandsenIndex<T>& index) {
    return gulbrandsen_at(cos_theta, index);
  }
  // F0 and g from the reflectance-processed η, g clamped to [0, 1].
  static std::vector<double> derive(const DeriveInput& in) {
    return gulbrandsen_params(in.derived.f0, in.derived.g_refl_eta);
  }
  // g from the point-sampled η, and a mid edge tint.
  static std::vector<std::vector<double>> extra_starts(const DeriveInput& in) {
    return {gulbrandsen_params(in.derived.f0, in.derived.g_ps_eta),
            gulbrandsen_params(in.derived.f0, {0.5, 0.5, 0.5})};
  }
  static std::vector<double> example() { return {0.93, 0.35, 0.68, 0.55, 0.30, 0.75}; }
};

}  // namespace models
}  // namespace fl::fresnel
