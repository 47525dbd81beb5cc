#pragma once
// Hoffman's F82 model: F0 and F82 per channel.
#include <array>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/model_spec.h"
#include "fresnel/models/schlick.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

// Hoffman 2019: Lazányi's form with α = 6 and a chosen so that the curve passes through F82 at
// cosθ = 1/7. 823543/46656 = 7⁷/6⁶ = 1/(c(1 − c)⁶) and 49/6 = (1 − c)⁵/(c(1 − c)⁶) at c = 1/7.
template <class T>
T f82_coefficient(T f0, T f82) {
  return T(823543.0 / 46656.0) * (f0 - f82) + T(49.0 / 6.0) * (T(1.0) - f0);
}
template <class T>
T hoffman_f82_unclamped(T cos_theta, T f0, T f82) {
  const T m = T(1.0) - cos_theta;
  const T m2 = m * m;
  return schlick(cos_theta, f0) - f82_coefficient(f0, f82) * cos_theta * (m2 * m2 * m2);
}
// Hoffman 2019, with the output clamped to [0, 1].
template <class T>
T hoffman_f82(T cos_theta, T f0, T f82) {
  const T f = hoffman_f82_unclamped(cos_theta, f0, f82);
  if (f < T(0.0)) return T(0.0);
  if (f > T(1.0)) return T(1.0);
  return f;
}

namespace models {

struct F82 {
  static constexpr const char* kName = "f82";
  static constexpr const char* kLabel = "Hoffman 2019 F82 (F0, F82)";
  static constexpr std::array<ParamSpec, 2> kChannelParams{{
      {"f0", "reflectance", ParamKind::Reflectance, kReflectanceFit, {-kUnbounded, kUnbounded}},
      {"f82", "reflectance", ParamKind::Reflectance, kReflectanceFit, {-kUnbounded, kUnbounded}},
  }};
  static constexpr std::array<ParamSpec, 0> kSharedParams{};
  static constexpr bool kCanLeaveUnitRange = false;
  static constexpr UnitFeatures kFeatures{
      .output_clamp = true, .closed_form_average = true, .table_terms = true, .identifiable = true};

  // Schlick's terms plus the F82 term μ(1 − μ)⁶ weighed by −a (f82_coefficient).
  static constexpr TermWeight kTableTerms[] = {
      {Term::One, "f0"}, {Term::Schlick, "1.0 - f0"}, {Term::F82, "-fl_f82_coefficient(f0, f82)"}};
  static constexpr ShaderHelper kCoefficientShader{"fl_f82_coefficient",
                                                   R"(vec3 fl_f82_coefficient(vec3 f0, vec3 f82) {
  return (823543.0 / 46656.0) * (f0 - f82) + (49.0 / 6.0) * (1.0 - f0);
}
)"};
  static constexpr const ShaderHelper* kShaderHelpers[] = {&kCoefficientShader};
  // Pre-integrated, the output clamp cannot be applied: the tables integrate the formula itself.
  static constexpr ShaderCode kShader{kShaderHelpers, R"(  float m = 1.0 - cos_theta;
  float m2 = m * m;
  vec3 a = fl_f82_coefficient(f0, f82);
  return clamp(f0 + (1.0 - f0) * (m2 * m2 * m) - a * (cos_theta * m2 * m2 * m2), 0.0, 1.0);
)"};

  template <class T>
  static T channel(T cos_theta, const T* p, const T*) {
    return hoffman_f82(cos_theta, p[0], p[1]);
  }
  // The formula itself, linear in (F0, F82), for comparisons of linearity.
  template <class T>
  static T channel_unclamped(T cos_theta, const T* p, const T*) {
    return hoffman_f82_unclamped(cos_theta, p[0], p[1]);
  }
  static TableTerms table_terms(const double* p, const double*) {
    TableTerms w;
    w[Term::One] = p[0];
    w[Term::Schlick] = 1.0 - p[0];
    w[Term::F82] = -f82_coefficient(p[0], p[1]);
    return w;
  }
  // Schlick's 1/21, minus a·2∫μ²(1 − μ)⁶ dμ = a·2·B(3, 7) = a/126 (the formula, unclamped).
  static double average(const double* p, const double*) {
    return p[0] + (1.0 - p[0]) / 21.0 - f82_coefficient(p[0], p[1]) / 126.0;
  }
  // The spectral F0 and F82.
  static std::vector<double> derive(const DeriveInput& in) {
    std::vector<double> p;
    for (int c = 0; c < 3; ++c) p.insert(p.end(), {in.derived.f0[c], in.derived.f82[c]});
    return p;
  }
  static std::vector<std::vector<double>> extra_starts(const DeriveInput&) { return {}; }
  static std::vector<double> example() { return {0.93, 0.90, 0.68, 0.72, 0.30, 0.45}; }
};

}  // namespace models
}  // namespace fl::fresnel
