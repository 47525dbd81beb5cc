#pragma once
// The basis models basis3, basis4, basis5: per channel, the coefficients of the first K terms of
// the Fresnel basis {1, b1, b2, b3, b4} (fresnel/basis.h, docs/basis.md), every term a
// table term, so that IBL and area lights pre-integrate them exactly.
#include <array>
#include <span>
#include <type_traits>
#include <vector>

#include "fresnel/basis.h"
#include "fresnel/derive.h"
#include "fresnel/ground_truth.h"
#include "fresnel/model_spec.h"
#include "fresnel/unit.h"

namespace fl::fresnel {

// Term k of the basis as a table term.
inline constexpr Term kBasisTableTerm[kBasisTerms] = {Term::One, Term::B1, Term::B2, Term::B3,
                                                      Term::B4};

// The value of a number that may carry derivatives (float or double as it is, color::Dual, a Ceres
// Jet).
template <class T>
auto primal(const T& x) {
  if constexpr (std::is_arithmetic_v<T>)
    return x;
  else if constexpr (requires { x.v; })
    return x.v;
  else
    return x.a;
}

// F = Σ_k c_k·b_k(μ), the formula itself (no clamp: the tables integrate it as it is). The angle
// is data, never a variable: the terms are evaluated in double, whatever T carries.
template <class T>
T basis_curve(T cos_theta, const T* c, int terms) {
  const auto mu = primal(cos_theta);
  T f = c[0];
  for (int k = 1; k < terms; ++k) f = f + c[k] * basis_term(k, mu);
  return f;
}

// The least-squares coefficients of the ground-truth RGB curve, per channel (the curve computed
// from the spectrum at the input's angles, or 91 angles uniform in θ, when it is not given).
inline std::vector<double> basis_projection(const DeriveInput& in, int terms) {
  std::vector<double> mu(in.cos_thetas.begin(), in.cos_thetas.end());
  std::vector<color::Rgb> truth(in.truth.begin(), in.truth.end());
  if (mu.empty())
    for (int j = 0; j <= 90; ++j) mu.push_back(std::cos(j * 3.14159265358979323846 / 180.0));
  if (truth.size() != mu.size()) {
    const std::vector<color::Rgb> weights(in.rgb_weights.begin(), in.rgb_weights.end());
    truth.clear();
    for (double c : mu)
      truth.push_back(spectral_reflectance_rgb(weights, in.ior, c, in.eta_outside));
  }
  std::vector<double> p;
  for (int ch = 0; ch < 3; ++ch) {
    std::vector<double> f;
    for (const auto& rgb : truth) f.push_back(rgb[ch]);
    const auto c = basis_coefficients(mu, f, terms);
    p.insert(p.end(), c.begin(), c.begin() + terms);
  }
  return p;
}

namespace models {

// The coefficients c0..c4 (c0 of 1, c1.. of b1..).
inline constexpr ParamSpec kBasisParams[kBasisTerms] = {
    {"c0", "weight of 1", ParamKind::Coefficient, {-0.5, 1.5}, {-kUnbounded, kUnbounded}},
    {"c1", "weight of b1", ParamKind::Coefficient, {-0.5, 1.5}, {-kUnbounded, kUnbounded}},
    {"c2", "weight of b2", ParamKind::Coefficient, {-1.0, 1.0}, {-kUnbounded, kUnbounded}},
    {"c3", "weight of b3", ParamKind::Coefficient, {-1.0, 1.0}, {-kUnbounded, kUnbounded}},
    {"c4", "weight of b4", ParamKind::Coefficient, {-1.0, 1.0}, {-kUnbounded, kUnbounded}},
};
inline constexpr TermWeight kBasisWeights[kBasisTerms] = {
    {Term::One, "c0"}, {Term::B1, "c1"}, {Term::B2, "c2"}, {Term::B3, "c3"}, {Term::B4, "c4"}};
inline constexpr const char* kBasisNames[] = {"", "", "basis2", "basis3", "basis4", "basis5"};
inline constexpr const char* kBasisLabels[] = {"",
                                               "",
                                               "Fresnel basis, 2 terms",
                                               "Fresnel basis, 3 terms (c0..c2)",
                                               "Fresnel basis, 4 terms (c0..c3)",
                                               "Fresnel basis, 5 terms (c0..c4)"};
// Gold-like coefficients per channel (for benchmarks and examples).
inline constexpr double kBasisExample[3][kBasisTerms] = {{0.93, 0.06, 0.02, -0.01, 0.004},
                                                         {0.68, 0.30, 0.03, -0.02, 0.003},
                                                         {0.30, 0.62, 0.05, -0.02, 0.002}};

template <int K>
constexpr std::array<ParamSpec, K> basis_params() {
  std::array<ParamSpec, K> a{};
  for (int k = 0; k < K; ++k) a[k] = kBasisParams[k];
  return a;
}

template <int K>
struct Basis {
  static_assert(K >= 2 && K <= kBasisTerms, "the basis has 2 to kBasisTerms terms");
  static constexpr const char* kName = kBasisNames[K];
  static constexpr const char* kLabel = kBasisLabels[K];
  static constexpr std::array<ParamSpec, K> kChannelParams = basis_params<K>();
  static constexpr std::array<ParamSpec, 0> kSharedParams{};
  static constexpr bool kCanLeaveUnitRange = true;
  static constexpr UnitFeatures kFeatures{
      .closed_form_average = true, .table_terms = true, .identifiable = true};

  // Every term is a table term, c_k its weight: the emitter writes the shader functions.
  static constexpr std::span<const TermWeight> kTableTerms =
      std::span<const TermWeight>(kBasisWeights).first(K);
  static constexpr ShaderCode kShader{};

  template <class T>
  static T channel(T cos_theta, const T* p, const T*) {
    return basis_curve(cos_theta, p, K);
  }
  static TableTerms table_terms(const double* p, const double*) {
    TableTerms w;
    for (int k = 0; k < K; ++k) w[kBasisTableTerm[k]] = p[k];
    return w;
  }
  // Each term's hemispherical average 2∫b μ dμ: 1 and kBasisAverage.
  static double average(const double* p, const double*) {
    double a = p[0];
    for (int k = 1; k < K; ++k) a += p[k] * kBasisAverage[k - 1];
    return a;
  }
  // The projection of the ground-truth curve on the first K terms, per channel.
  static std::vector<double> derive(const DeriveInput& in) { return basis_projection(in, K); }
  static std::vector<std::vector<double>> extra_starts(const DeriveInput&) { return {}; }
  static std::vector<double> example() {
    std::vector<double> p;
    for (const auto& ch : kBasisExample) p.insert(p.end(), ch, ch + K);
    return p;
  }
};

}  // namespace models
}  // namespace fl::fresnel
