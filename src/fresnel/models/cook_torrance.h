#pragma once
// Cook-Torrance colour interpolation: F0 per channel, one representative complex index shared.
#include <array>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/exact.h"
#include "fresnel/exact_shader.h"
#include "fresnel/model.h"

namespace fl::fresnel {

// Cook & Torrance 1982 colour interpolation in Hoffman's modified form: the scalar Fresnel curve
// F′ of one representative index shapes the colour change from F0 to 1.
template <class T>
T cook_torrance(T cos_theta, T f0, T eta_rep, T kappa_rep) {
  const T fp = fresnel_conductor(cos_theta, eta_rep, kappa_rep);
  const T fp0 = fresnel_conductor(T(1.0), eta_rep, kappa_rep);
  T t = (fp - fp0) / (T(1.0) - fp0);
  if (t < T(0.0)) t = T(0.0);
  return f0 + (T(1.0) - f0) * t;
}

namespace models {

struct CookTorrance {
  static constexpr const char* kName = "cook_torrance";
  static constexpr const char* kLabel = "Cook-Torrance colour interpolation";
  static constexpr std::array<ParamSpec, 1> kChannelParams{
      {{"f0", "reflectance", ParamKind::Reflectance, {0.0, 1.0}, {-kUnbounded, kUnbounded}}}};
  static constexpr std::array<ParamSpec, 2> kSharedParams{{
      {"eta_rep", "relative index", ParamKind::Index, {0.01, 10.0}, {-kUnbounded, kUnbounded}},
      {"kappa_rep", "extinction", ParamKind::Index, {0.0, 20.0}, {-kUnbounded, kUnbounded}},
  }};
  static constexpr bool kCanLeaveUnitRange = false;
  // The shape comes from the exact equations of a per-material index: no shared table holds it.
  static constexpr PreIntegration kPreIntegration = kEvaluatedAtNdotV;
  // The representative index in all three lanes of the vector helper.
  static constexpr ShaderCode kShader{kConductorHelpers, R"(  vec3 eta = vec3(eta_rep, eta_rep, eta_rep);
  vec3 kappa = vec3(kappa_rep, kappa_rep, kappa_rep);
  float fp = fl_fresnel_conductor(cos_theta, eta, kappa).x;
  float fp0 = fl_fresnel_conductor(1.0, eta, kappa).x;
  return f0 + (1.0 - f0) * max((fp - fp0) / (1.0 - fp0), 0.0);
)"};

  template <class T>
  static T channel(T cos_theta, const T* p, const T* shared) {
    return cook_torrance(cos_theta, p[0], shared[0], shared[1]);
  }
  // F0 and the luminance (Y) of the reflectance-processed η, κ.
  static std::vector<double> derive(const DerivedParameters& d) {
    return {d.f0.r, d.f0.g, d.f0.b, d.eta_rep, d.kappa_rep};
  }
  // The green channel's reflectance-processed index.
  static std::vector<std::vector<double>> extra_starts(const DerivedParameters& d) {
    return {{d.f0.r, d.f0.g, d.f0.b, d.eta_refl.g, d.kappa_refl.g}};
  }
  static std::vector<double> example() { return {0.93, 0.68, 0.30, 0.35, 2.6}; }
};

}  // namespace models
}  // namespace fl::fresnel
