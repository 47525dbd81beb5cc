#pragma once
// The Schlick model: F0 per channel.
#include <array>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/model_spec.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

// Schlick 1994: F = F0 + (1 − F0)(1 − cosθ)⁵.
template <class T>
T schlick(T cos_theta, T f0) {
  const T m = T(1.0) - cos_theta;
  const T m2 = m * m;
  return f0 + (T(1.0) - f0) * (m2 * m2 * m);
}

namespace models {

struct Schlick {
  static constexpr const char* kName = "schlick";
  static constexpr const char* kLabel = "Schlick";
  static constexpr std::array<ParamSpec, 1> kChannelParams{
      {{"f0", "reflectance", ParamKind::Reflectance, kReflectanceFit, {-kUnbounded, kUnbounded}}}};
  static constexpr std::array<ParamSpec, 0> kSharedParams{};
  static constexpr bool kCanLeaveUnitRange = false;
  static constexpr UnitFeatures kFeatures{
      .closed_form_average = true, .table_terms = true, .identifiable = true};

  // F0·1 + (1 − F0)·(1 − μ)⁵: the split-sum DFG scale and bias and the LTC Schlick moment
  // integrate it exactly.
  static constexpr TermWeight kTableTerms[] = {{Term::One, "f0"}, {Term::Schlick, "1.0 - f0"}};
  static constexpr ShaderCode kShader{{}, R"(  float m = 1.0 - cos_theta;
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
)"};

  template <class T>
  static T channel(T cos_theta, const T* p, const T*) {
    return schlick(cos_theta, p[0]);
  }
  // F0·1 + (1 − F0)·(1 − μ)⁵.
  static TableTerms table_terms(const double* p, const double*) {
    TableTerms w;
    w[Term::One] = p[0];
    w[Term::Schlick] = 1.0 - p[0];
    return w;
  }
  // 2∫(1 − μ)⁵μ dμ = 2·B(2, 6) = 1/21.
  static double average(const double* p, const double*) { return p[0] + (1.0 - p[0]) / 21.0; }
  // The spectral F0.
  static std::vector<double> derive(const DeriveInput& in) {
    return {in.derived.f0.r, in.derived.f0.g, in.derived.f0.b};
  }
  static std::vector<std::vector<double>> extra_starts(const DeriveInput&) { return {}; }
  // Gold in ACEScg, roughly (for benchmarks and examples).
  static std::vector<double> example() { return {0.93, 0.68, 0.30}; }
};

}  // namespace models
}  // namespace fl::fresnel
