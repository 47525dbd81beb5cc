#include "fresnel/registered_models.h"

#include <fmt/format.h>

#include <algorithm>

#include "fresnel/registry.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::fresnel {
namespace {

template <class Unit>
constexpr bool kHasOutputClamp = Unit::kFeatures.output_clamp;

// Unit with its output clamp removed (where it has one).
template <class Unit>
struct Unclamped : Unit {
  template <class T>
  static T channel(T cos_theta, const T* p, const T* shared) {
    if constexpr (kHasOutputClamp<Unit>)
      return Unit::channel_unclamped(cos_theta, p, shared);
    else
      return Unit::channel(cos_theta, p, shared);
  }
};

// Channel c's parameters and the shared ones, from the flat layout.
template <class Unit>
const double* channel_params(const double* params, int c) {
  return params + c * static_cast<int>(Unit::kChannelParams.size());
}
template <class Unit>
const double* shared_params(const double* params) {
  return params + 3 * static_cast<int>(Unit::kChannelParams.size());
}
template <class Unit>
TableTerms table_terms_flat(const double* params, int c) {
  return Unit::table_terms(channel_params<Unit>(params, c), shared_params<Unit>(params));
}
template <class Unit>
double average_flat(const double* params, int c) {
  return Unit::average(channel_params<Unit>(params, c), shared_params<Unit>(params));
}

template <class Unit>
constexpr TableTerms (*table_terms_of())(const double*, int) {
  if constexpr (Unit::kFeatures.table_terms)
    return &table_terms_flat<Unit>;
  else
    return nullptr;
}
template <class Unit>
constexpr double (*average_of())(const double*, int) {
  if constexpr (Unit::kFeatures.closed_form_average)
    return &average_flat<Unit>;
  else
    return nullptr;
}

// The table terms' GLSL weights of a pre-integrable unit (none for the others), and the channels
// they read under IBL and area lights (table_channels), kept for the program's lifetime.
template <class Unit>
constexpr std::span<const TermWeight> term_weights_of() {
  if constexpr (Unit::kFeatures.table_terms)
    return Unit::kTableTerms;
  else
    return {};
}
template <class Unit>
inline constexpr TableChannels kIblChannels = table_channels(term_weights_of<Unit>(), true);
template <class Unit>
inline constexpr TableChannels kAreaChannels = table_channels(term_weights_of<Unit>(), false);
template <class Unit>
constexpr PreIntegration pre_integration_of() {
  if constexpr (Unit::kFeatures.table_terms)
    return {kPunctualAtVdotH,
            {kIblChannels<Unit>.span(), true, ""},
            {kAreaChannels<Unit>.span(), true, ""}};
  else
    return kEvaluatedAtNdotV;
}

template <class Unit>
color::Rgb evaluate_flat(double cos_theta, const double* params, bool unclamped) {
  if (unclamped) return evaluate_unit<Unclamped<Unit>>(cos_theta, params);
  return evaluate_unit<Unit>(cos_theta, params);
}

template <class Unit>
ModelSpec make_spec() {
  return {model_of<Unit>,
          Unit::kName,
          Unit::kLabel,
          {Unit::kChannelParams.begin(), Unit::kChannelParams.end()},
          {Unit::kSharedParams.begin(), Unit::kSharedParams.end()},
          pre_integration_of<Unit>(),
          Unit::kShader,
          term_weights_of<Unit>(),
          Unit::kCanLeaveUnitRange,
          kHasOutputClamp<Unit>,
          Unit::kFeatures.identifiable,
          &evaluate_flat<Unit>,
          &evaluate_unit<Unit, float>,
          &detail::batch_channels<Unit, float>,
          &detail::batch_channels<Unit, double>,
          table_terms_of<Unit>(),
          average_of<Unit>()};
}

template <class... Units>
std::vector<ModelSpec> make_specs(ModelList<Units...>) {
  return {make_spec<Units>()...};
}

std::vector<color::Rgb> curve(Model m, const std::vector<double>& params,
                              const std::vector<double>& cos_thetas, bool unclamped) {
  const auto& spec = model_spec(m);
  if (static_cast<int>(params.size()) != spec.param_count())
    throw std::invalid_argument(fmt::format("{}: {} parameters, expected {}", spec.name,
                                            params.size(), spec.param_count()));
  std::vector<color::Rgb> out;
  out.reserve(cos_thetas.size());
  for (double c : cos_thetas) out.push_back(spec.evaluate(c, params.data(), unclamped));
  return out;
}

}  // namespace

const std::vector<ModelSpec>& model_specs() {
  static const std::vector<ModelSpec> specs = make_specs(Registry{});
  return specs;
}

const ModelSpec& model_spec(Model m) {
  const auto& specs = model_specs();
  if (m.index() < 0 || m.index() >= static_cast<int>(specs.size()))
    throw std::logic_error("unknown model");
  return specs[static_cast<size_t>(m.index())];
}

const ModelSpec& model_from_name(const std::string& name) {
  // Names match ignoring case and '-' versus '_'; British spelling accepted.
  std::vector<NameChoice> choices;
  for (const auto& s : model_specs()) {
    choices.push_back({s.name, {}});
    if (std::string(s.name) == "generalized_schlick")
      choices.back().aliases = {"generalised_schlick"};
  }
  if (const auto match = match_name(name, choices))
    for (const auto& s : model_specs())
      if (*match == s.name) return s;
  throw InputError(unknown_name_message("model", name, choices));
}

std::vector<color::Rgb> evaluate_curve(Model m, const std::vector<double>& params,
                                       const std::vector<double>& cos_thetas) {
  return curve(m, params, cos_thetas, false);
}

std::vector<color::Rgb> evaluate_curve_unclamped(Model m, const std::vector<double>& params,
                                                 const std::vector<double>& cos_thetas) {
  return curve(m, params, cos_thetas, true);
}

bool output_clamped(Model m, const std::vector<double>& params,
                    const std::vector<double>& cos_thetas) {
  const auto& spec = model_spec(m);
  if (!spec.has_output_clamp) return false;
  for (double c : cos_thetas) {
    const auto a = spec.evaluate(c, params.data(), false),
               b = spec.evaluate(c, params.data(), true);
    if (a.r != b.r || a.g != b.g || a.b != b.b) return true;
  }
  return false;
}

int reflectances_outside_unit(Model m, const std::vector<double>& params) {
  const auto& spec = model_spec(m);
  const int pc = spec.per_channel();
  int n = 0;
  for (int j = 0; j < pc; ++j) {
    if (spec.channel_params[j].kind != ParamKind::Reflectance) continue;
    for (int ch = 0; ch < 3; ++ch) n += params[ch * pc + j] < 0.0 || params[ch * pc + j] > 1.0;
  }
  return n;
}

int clamp_to_domain(Model m, std::vector<double>& params) {
  const auto domain = model_spec(m).domain();
  int moved = 0;
  for (size_t i = 0; i < params.size() && i < domain.size(); ++i) {
    if (domain[i].lo == -kUnbounded && domain[i].hi == kUnbounded) continue;
    const double c = std::clamp(params[i], domain[i].lo, domain[i].hi);
    moved += c != params[i];
    params[i] = c;
  }
  return moved;
}

std::vector<double> derived_model_params(Model m, const DeriveInput& in) {
  std::vector<double> p;
  visit_model(m, [&](auto unit) { p = decltype(unit)::derive(in); });
  return p;
}

std::vector<std::vector<double>> fit_starts(Model m, const DeriveInput& in) {
  std::vector<std::vector<double>> s{derived_model_params(m, in)};
  visit_model(m, [&](auto unit) {
    for (auto& p : decltype(unit)::extra_starts(in)) s.push_back(std::move(p));
  });
  return s;
}

std::vector<double> example_params(Model m) {
  std::vector<double> p;
  visit_model(m, [&](auto unit) { p = decltype(unit)::example(); });
  return p;
}

std::string model_names() {
  std::string s;
  for (const auto& m : model_specs()) s += (s.empty() ? "" : ", ") + std::string(m.name);
  return s;
}

}  // namespace fl::fresnel
