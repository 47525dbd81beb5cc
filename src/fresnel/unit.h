#pragma once
// The closed model unit: what every entry of the registry must declare, checked at compile time.
// A unit (models/NAME.h) is a struct with
//   kName, kLabel                      const char*: command-line name, label for people
//   kChannelParams, kSharedParams      std::array<ParamSpec, N> (model_spec.h's parameter layout)
//   kCanLeaveUnitRange                 bool
//   kShader                            ShaderCode
//   kFeatures                          UnitFeatures: the optional members it has
//   channel<T>(cos_theta, p, shared)   the kernel, for double and float (and autodiff scalars)
//   derive(DeriveInput), extra_starts(DeriveInput), example()
// and, exactly when kFeatures declares them, the optional members below. How an engine shades the
// model per lighting (PreIntegration) follows: a unit with table terms is pre-integrated under IBL
// and area lights, reading the channels of its terms (table_channels); one without is evaluated at
// n·v (kEvaluatedAtNdotV). A missing or misspelled
// member, or a feature declared without its member (or a member without its feature), is a
// compile error naming it: the registry (registry.h) static_asserts every entry.
#include <concepts>
#include <span>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/model_spec.h"

namespace fl::fresnel {

// The optional parts of a unit, declared rather than detected.
struct UnitFeatures {
  // channel_unclamped<T>(cos_theta, p, shared): the kernel without its output clamp (the formula
  // itself, for comparisons of linearity).
  bool output_clamp = false;
  // average(p, shared) -> double: the closed form of channel p's hemispherical average 2∫F μ dμ.
  bool closed_form_average = false;
  // kTableTerms: the table terms the model weighs, once, each with its weight as a GLSL vec3
  // expression of the parameters (TermWeight; the emitter writes the IBL and area functions from
  // them), and table_terms(p, shared) -> TableTerms: the same weights in C++ for channel p (the
  // Vulkan tests run the generated GLSL against them).
  bool table_terms = false;
  // prepare<T>(p, shared) and channel_at<T>(cos_theta, prepared): channel() split at the angle.
  bool prepared_channel = false;
  // The parameters are identifiable from a curve: a fit from a nearby start recovers them (the
  // generic tests check it). False where several parameter sets draw nearly the same curve.
  bool identifiable = false;
};

namespace unit_check {

template <class U>
concept Identity = requires {
  { U::kName } -> std::convertible_to<const char*>;
  { U::kLabel } -> std::convertible_to<const char*>;
};

template <class U>
concept Parameters = requires {
  {std::span<const ParamSpec>(U::kChannelParams)};
  {std::span<const ParamSpec>(U::kSharedParams)};
  { U::kCanLeaveUnitRange } -> std::convertible_to<bool>;
};

template <class U>
concept Declarations = requires {
  { U::kShader } -> std::convertible_to<ShaderCode>;
  { U::kFeatures } -> std::convertible_to<UnitFeatures>;
};

template <class U>
concept Kernel = requires(double cd, const double* pd, float cf, const float* pf) {
  { U::channel(cd, pd, pd) } -> std::same_as<double>;
  { U::channel(cf, pf, pf) } -> std::same_as<float>;
};

template <class U>
concept Derivation = requires(const DeriveInput& in) {
  { U::derive(in) } -> std::same_as<std::vector<double>>;
  { U::extra_starts(in) } -> std::same_as<std::vector<std::vector<double>>>;
  { U::example() } -> std::same_as<std::vector<double>>;
};

template <class U>
concept HasUnclamped = requires(double c, const double* p) {
  { U::channel_unclamped(c, p, p) } -> std::same_as<double>;
};
template <class U>
concept HasAverage = requires(const double* p) {
  { U::average(p, p) } -> std::same_as<double>;
};
template <class U>
concept HasTableTerms = requires(const double* p) {
  { U::table_terms(p, p) } -> std::same_as<TableTerms>;
  {std::span<const TermWeight>(U::kTableTerms)};
};
template <class U>
concept HasPrepared = requires(double c, const double* p) {
  U::channel_at(c, U::prepare(p, p));
};

template <class U>
concept FeaturesMatchMembers =
    U::kFeatures.output_clamp == HasUnclamped<U>&& U::kFeatures.closed_form_average ==
    HasAverage<U>&& U::kFeatures.table_terms == HasTableTerms<U>&& U::kFeatures.prepared_channel ==
    HasPrepared<U>;

}  // namespace unit_check

template <class U>
concept ModelUnit =
    unit_check::Identity<U> && unit_check::Parameters<U> && unit_check::Declarations<U> &&
    unit_check::Kernel<U> && unit_check::Derivation<U> && unit_check::FeaturesMatchMembers<U>;

// Every requirement of ModelUnit, one static_assert each, so that the error names what is wrong.
template <class U>
constexpr bool check_unit() {
  using namespace unit_check;
  static_assert(Identity<U>, "a model unit needs kName and kLabel (const char*)");
  static_assert(Parameters<U>,
                "a model unit needs kChannelParams and kSharedParams (std::array<ParamSpec, N>) "
                "and kCanLeaveUnitRange");
  static_assert(Declarations<U>, "a model unit needs kShader and kFeatures");
  static_assert(Kernel<U>,
                "a model unit needs template <class T> T channel(T, const T*, const T*)");
  static_assert(Derivation<U>,
                "a model unit needs derive(const DeriveInput&), extra_starts(const DeriveInput&) "
                "and example()");
  if constexpr (Declarations<U>) {
    static_assert(U::kFeatures.output_clamp == HasUnclamped<U>,
                  "kFeatures.output_clamp must be declared exactly when the unit has "
                  "channel_unclamped(cos_theta, p, shared)");
    static_assert(U::kFeatures.closed_form_average == HasAverage<U>,
                  "kFeatures.closed_form_average must be declared exactly when the unit has "
                  "average(p, shared)");
    static_assert(U::kFeatures.table_terms == HasTableTerms<U>,
                  "kFeatures.table_terms must be declared exactly when the unit has kTableTerms "
                  "(std::span<const TermWeight>) and table_terms(p, shared)");
    static_assert(U::kFeatures.prepared_channel == HasPrepared<U>,
                  "kFeatures.prepared_channel must be declared exactly when the unit has "
                  "prepare(p, shared) and channel_at(cos_theta, prepared)");
  }
  return ModelUnit<U>;
}

}  // namespace fl::fresnel
