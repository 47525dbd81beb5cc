#pragma once
// Lazányi's model: F0, a and α per channel.
#include <array>
#include <cmath>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/model_spec.h"
#include "fresnel/models/f82.h"
#include "fresnel/models/schlick.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

// Lazányi & Szirmay-Kalos 2005: Schlick minus a·cosθ·(1 − cosθ)^α.
template <class T>
T lazanyi(T cos_theta, T f0, T a, T alpha) {
  using std::pow;
  const T m = T(1.0) - cos_theta;
  if (m <= T(0.0)) return f0;
  return schlick(cos_theta, f0) - a * cos_theta * pow(m, alpha);
}

namespace models {

struct Lazanyi {
  static constexpr const char* kName = "lazanyi";
  static constexpr const char* kLabel = "Lazanyi 2005 (F0, a, alpha)";
  static constexpr std::array<ParamSpec, 3> kChannelParams{{
      {"f0", "reflectance", ParamKind::Reflectance, kReflectanceFit, {-kUnbounded, kUnbounded}},
      {"a", "coefficient", ParamKind::Coefficient, {-10.0, 30.0}, {-kUnbounded, kUnbounded}},
      // α ends below 1 for some crystals (main/MoO3/nk/Vos: 0.83 in blue).
      {"alpha", "exponent", ParamKind::Exponent, {0.1, 20.0}, {0.01, kUnbounded}},
  }};
  static constexpr std::array<ParamSpec, 0> kSharedParams{};
  static constexpr bool kCanLeaveUnitRange = true;
  static constexpr UnitFeatures kFeatures{.closed_form_average = true};
  // No table terms: a per-channel exponent α (only α = 6, the F82 model, has one).
  static constexpr ShaderCode kShader{{}, R"(  float m = 1.0 - cos_theta;
  if (m <= 0.0) return f0;
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m) - a * cos_theta * pow(vec3(m, m, m), alpha);
)"};
  // Schlick's 1/21, minus a·2∫μ²(1 − μ)^α dμ = a·2·B(3, α + 1) = 4a/((α + 1)(α + 2)(α + 3)).
  static double average(const double* p, const double*) {
    return p[0] + (1.0 - p[0]) / 21.0 - 4.0 * p[1] / ((p[2] + 1.0) * (p[2] + 2.0) * (p[2] + 3.0));
  }

  template <class T>
  static T channel(T cos_theta, const T* p, const T*) {
    return lazanyi(cos_theta, p[0], p[1], p[2]);
  }
  // α = 6 and a through the measured F82 (the F82 model's coefficient).
  static std::vector<double> derive(const DeriveInput& in) {
    std::vector<double> p;
    for (int c = 0; c < 3; ++c)
      p.insert(p.end(),
               {in.derived.f0[c], f82_coefficient(in.derived.f0[c], in.derived.f82[c]), 6.0});
    return p;
  }
  // Plain Schlick with a shallower and a steeper exponent.
  static std::vector<std::vector<double>> extra_starts(const DeriveInput& in) {
    std::vector<std::vector<double>> s;
    for (double alpha : {3.0, 10.0}) {
      std::vector<double> p;
      for (int c = 0; c < 3; ++c) p.insert(p.end(), {in.derived.f0[c], 0.0, alpha});
      s.push_back(p);
    }
    return s;
  }
  static std::vector<double> example() { return {0.93, 0.1, 6.0, 0.68, 0.3, 6.0, 0.30, 0.8, 6.0}; }
};

}  // namespace models
}  // namespace fl::fresnel
