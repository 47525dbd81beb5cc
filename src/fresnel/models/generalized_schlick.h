#pragma once
// Generalized Schlick: F0, F90 and exponent p per channel.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/model_spec.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

// Generalized Schlick (OpenPBR, MaterialX generalized_schlick_bsdf): F0 + (F90 − F0)(1 − cosθ)^p.
template <class T>
T generalized_schlick(T cos_theta, T f0, T f90, T p) {
  using std::pow;
  const T m = T(1.0) - cos_theta;
  if (m <= T(0.0)) return f0;
  return f0 + (f90 - f0) * pow(m, p);
}

namespace models {

struct GeneralizedSchlick {
  static constexpr const char* kName = "generalized_schlick";
  static constexpr const char* kLabel = "Generalized Schlick (F0, F90, p)";
  // p reaches 30 for metals whose curve dips before grazing (main/Mo/nk/Werner, main/W/nk/Werner):
  // searched up to 100, where (1 − cosθ)^p stays below 1e-4 up to 85°.
  static constexpr ParamRange kExponentFit{0.1, 100.0};
  static constexpr std::array<ParamSpec, 3> kChannelParams{{
      {"f0", "reflectance", ParamKind::Reflectance, kReflectanceFit, {-kUnbounded, kUnbounded}},
      {"f90", "reflectance", ParamKind::Reflectance, kReflectanceFit, {-kUnbounded, kUnbounded}},
      {"p", "exponent", ParamKind::Exponent, kExponentFit, {0.01, kUnbounded}},
  }};
  static constexpr std::array<ParamSpec, 0> kSharedParams{};
  static constexpr bool kCanLeaveUnitRange = true;
  static constexpr UnitFeatures kFeatures{.closed_form_average = true};
  // No table terms: a per-material exponent.
  static constexpr ShaderCode kShader{{}, R"(  float m = 1.0 - cos_theta;
  if (m <= 0.0) return f0;
  return f0 + (f90 - f0) * pow(vec3(m, m, m), p);
)"};
  // 2∫μ(1 − μ)^p dμ = 2·B(2, p + 1) = 2/((p + 1)(p + 2)).
  static double average(const double* p, const double*) {
    return p[0] + (p[1] - p[0]) * 2.0 / ((p[2] + 1.0) * (p[2] + 2.0));
  }

  template <class T>
  static T channel(T cos_theta, const T* p, const T*) {
    return generalized_schlick(cos_theta, p[0], p[1], p[2]);
  }
  // F0, F90 = 1, and p through the measured F82: F82 = F0 + (1 − F0)(6/7)^p ⇒
  // p = ln((F82 − F0)/(1 − F0)) / ln(6/7); Schlick's 5 when the curve dips below F0 there.
  static std::vector<double> derive(const DeriveInput& in) {
    std::vector<double> p;
    for (int c = 0; c < 3; ++c) {
      const double t = (in.derived.f82[c] - in.derived.f0[c]) / (1.0 - in.derived.f0[c]);
      const double pc = t > 0.0 && t < 1.0 ? std::log(t) / std::log(1.0 - kCosTheta82) : 5.0;
      p.insert(p.end(), {in.derived.f0[c], 1.0, std::clamp(pc, kExponentFit.lo, kExponentFit.hi)});
    }
    return p;
  }
  // Schlick's exponent.
  static std::vector<std::vector<double>> extra_starts(const DeriveInput& in) {
    std::vector<double> p;
    for (int c = 0; c < 3; ++c) p.insert(p.end(), {in.derived.f0[c], 1.0, 5.0});
    return {p};
  }
  static std::vector<double> example() { return {0.93, 1.0, 5.2, 0.68, 1.0, 5.6, 0.30, 1.0, 6.1}; }
};

}  // namespace models
}  // namespace fl::fresnel
