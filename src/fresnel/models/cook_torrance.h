#pragma once
// Cook-Torrance colour interpolation: F0 per channel, one representative complex index shared.
#include <array>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/exact.h"
#include "fresnel/exact_shader.h"
#include "fresnel/model_spec.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

// Cook & Torrance 1982 colour interpolation in Hoffman's modified form: the scalar Fresnel curve
// F′ of one representative index shapes the colour change from F0 to 1.
// The part that does not depend on the angle: F0, the index and F′ at normal incidence.
template <class T>
struct CookTorranceShape {
  T f0, eta_rep, kappa_rep, fp0;
};
template <class T>
CookTorranceShape<T> cook_torrance_shape(T f0, T eta_rep, T kappa_rep) {
  return {f0, eta_rep, kappa_rep, fresnel_conductor(T(1.0), eta_rep, kappa_rep)};
}
template <class T>
T cook_torrance_at(T cos_theta, const CookTorranceShape<T>& s) {
  const T fp = fresnel_conductor(cos_theta, s.eta_rep, s.kappa_rep);
  T t = (fp - s.fp0) / (T(1.0) - s.fp0);
  if (t < T(0.0)) t = T(0.0);
  return s.f0 + (T(1.0) - s.f0) * t;
}
template <class T>
T cook_torrance(T cos_theta, T f0, T eta_rep, T kappa_rep) {
  return cook_torrance_at(cos_theta, cook_torrance_shape(f0, eta_rep, kappa_rep));
}

namespace models {

struct CookTorrance {
  static constexpr const char* kName = "cook_torrance";
  static constexpr const char* kLabel = "Cook-Torrance colour interpolation";
  static constexpr std::array<ParamSpec, 1> kChannelParams{
      {{"f0", "reflectance", ParamKind::Reflectance, kReflectanceFit, {-kUnbounded, kUnbounded}}}};
  static constexpr std::array<ParamSpec, 2> kSharedParams{{
      // As wide as RGB η, κ (fresnel_rgb.h). The shape's limit as η_rep → 0 is reached at 0.01:
      // fits
      // of silver end there, and going on to 1e-5 changes their RMS ΔE2000 by under 0.001 (0.079 at
      // 0.01, 0.080 at 1e-5, main/Ag/nk/Babar), so 0.01 is the domain's end, not a pin.
      {"eta_rep", "relative index", ParamKind::Index, {0.01, 1000.0}, {0.01, kUnbounded}},
      {"kappa_rep", "extinction", ParamKind::Extinction, {0.0, 1000.0}, {0.0, kUnbounded}},
  }};
  static constexpr bool kCanLeaveUnitRange = false;
  static constexpr UnitFeatures kFeatures{.prepared_channel = true};
  // The representative index in all three lanes of the vector helper.
  // No table terms: the shape comes from the exact equations of a per-material index.
  static constexpr ShaderCode kShader{kConductorHelpers,
                                      R"(  vec3 eta = vec3(eta_rep, eta_rep, eta_rep);
  vec3 kappa = vec3(kappa_rep, kappa_rep, kappa_rep);
  float fp = fl_fresnel_conductor(cos_theta, eta, kappa).x;
  float fp0 = fl_fresnel_conductor(1.0, eta, kappa).x;
  return f0 + (1.0 - f0) * max((fp - fp0) / (1.0 - fp0), 0.0);
)"};

  template <class T>
  static T channel(T cos_theta, const T* p, const T* shared) {
    return cook_torrance(cos_theta, p[0], shared[0], shared[1]);
  }
  // The channel split at the angle (prepare_channel, model_spec.h).
  template <class T>
  static CookTorranceShape<T> prepare(const T* p, const T* shared) {
    return cook_torrance_shape(p[0], shared[0], shared[1]);
  }
  template <class T>
  static T channel_at(T cos_theta, const CookTorranceShape<T>& shape) {
    return cook_torrance_at(cos_theta, shape);
  }
  // F0 and the luminance (Y) of the reflectance-processed η, κ.
  static std::vector<double> derive(const DeriveInput& in) {
    return {in.derived.f0.r, in.derived.f0.g, in.derived.f0.b, in.derived.eta_rep,
            in.derived.kappa_rep};
  }
  // The green channel's reflectance-processed index.
  static std::vector<std::vector<double>> extra_starts(const DeriveInput& in) {
    return {{in.derived.f0.r, in.derived.f0.g, in.derived.f0.b, in.derived.eta_refl.g,
             in.derived.kappa_refl.g}};
  }
  static std::vector<double> example() { return {0.93, 0.68, 0.30, 0.35, 2.6}; }
};

}  // namespace models
}  // namespace fl::fresnel
