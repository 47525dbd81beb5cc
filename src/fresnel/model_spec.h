#pragma once
// What every Fresnel model declares about itself. A model is one unit (one file in models/): its
// kernel, its parameters, its derivation from spectral data, its fit starts and what can
// pre-integrate it; unit.h states the members every unit must have (ModelUnit). The registry
// (registry.h) lists the units and checks each; everything else is generic.
//
// Parameter layout, shared by evaluation, derivation, fitting and reports: the per-channel
// parameters first (R block, G block, B block), then the parameters shared by the channels.
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "color/values.h"
#include "fresnel/table_terms.h"

namespace fl::fresnel {

struct ParamRange {
  double lo, hi;
};

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// The fit box of a reflectance parameter (F0, F82, F90). A reflectance in a working space leaves
// [0, 1] by its gamut excess (gold's F0_r is 1.041 in linear Rec.709; a saturated metal's channel
// dips below 0 in a narrow gamut), never by half: the box holds every real page and keeps a fit
// from wandering.
inline constexpr ParamRange kReflectanceFit{-0.5, 1.5};

// What a parameter stands for; reflectances are the ones reported when outside [0, 1]; extinction
// coefficients are held at 0 when a fit's material is lossless (fit.h).
enum class ParamKind { Reflectance, Index, Extinction, Exponent, Coefficient };

struct ParamSpec {
  const char* name;  // column name without the channel suffix: "f0", "eta_rep"
  const char* unit;  // for people: "reflectance", "relative index", ...
  ParamKind kind;
  ParamRange fit;  // the box a fit searches
  ParamRange
      domain;  // where the kernel is defined; converted or blended values are clamped into it
};

// What an engine needs to shade a model under one kind of lighting: the lookup-table channels it
// reads (named as the `lut` command writes them) and whether the Fresnel term itself is
// pre-integrated into them. When it is not, the engine evaluates the model once per pixel at
// `evaluated_at` (e.g. n·v) and scales the lobe's Fresnel-free integral: a stated approximation
// whose rendered error is measured, not hidden. Punctual lights read no table and evaluate the
// model exactly at each light's half vector (v·h).
struct LightingSupport {
  std::span<const char* const> channels;
  bool fresnel_pre_integrated = false;
  const char* evaluated_at = "";
};

// Under punctual lights (no table), image-based lighting (split-sum DFG table) and LTC area lights
// (LTC matrix and the GGX lobe's Fresnel moments).
struct PreIntegration {
  LightingSupport punctual, ibl, area;
};

// The channels the lookup tables provide. dfg1, dfg2: the split-sum scale and bias, ∫(1 − Fc)ρ cos
// and ∫Fc ρ cos with Fc = (1 − v·h)⁵; dfg_f82: ∫ μ(1 − μ)⁶ ρ cos (μ = v·h), the F82 term's
// analogue. ltc_matrix: the four entries of M⁻¹; n_d, f_d, l_d: the lobe's norm, Schlick moment and
// F82 moment (Hill's n_D, f_D and their F82 analogue).
// The term channels are named in the term registry (table_terms.h).
namespace lut_channel {
inline constexpr const char* kDfgScale = term_spec(Term::One).dfg.channel;
inline constexpr const char* kDfgBias = term_spec(Term::Schlick).dfg.channel;
inline constexpr const char* kDfgF82 = term_spec(Term::F82).dfg.channel;
inline constexpr const char* kLtcMatrix = "ltc_matrix";
inline constexpr const char* kLtcNorm = term_spec(Term::One).ltc.channel;
inline constexpr const char* kLtcSchlick = term_spec(Term::Schlick).ltc.channel;
inline constexpr const char* kLtcF82 = term_spec(Term::F82).ltc.channel;
// The lobe's Fresnel-free integral: dfg1 + dfg2 under IBL, n_d (with the matrix) under LTC.
inline constexpr const char* kLobeIbl[] = {kDfgScale, kDfgBias};
inline constexpr const char* kLobeArea[] = {kLtcMatrix, kLtcNorm};
}  // namespace lut_channel

// Punctual lights: the model itself at each light's v·h, no table.
inline constexpr LightingSupport kPunctualAtVdotH{{}, false, "v·h"};

// For a model no shared table can pre-integrate: F(n·v) times the lobe's Fresnel-free integral.
inline constexpr PreIntegration kEvaluatedAtNdotV{kPunctualAtVdotH,
                                                  {lut_channel::kLobeIbl, false, "n·v"},
                                                  {lut_channel::kLobeArea, false, "n·v"}};

// A pre-integrable model's Fresnel term per channel is TableTerms (table_terms.h): weights on the
// tables' terms, F(μ) = Σ_t w_t·term_t(μ), so that the lobe integrates to Σ_t w_t·∫term_t ρ cos.
// Its unit declares the terms it weighs once, each with its weight as a GLSL vec3 expression of
// the parameters (TermWeight); the channels an engine reads and every table shader follow from the
// term registry.
struct TermWeight {
  Term term;
  const char* glsl;
};

// The channels an engine reads to shade a combination of table terms, in the registry's order:
// under IBL each weighed term's DFG channel and the one it is stored less of, under area lights
// the LTC matrix and each weighed term's moment; the term 1 (the lobe's Fresnel-free integral)
// always.
struct TableChannels {
  std::array<const char*, kTermCount + 1> names{};
  std::size_t size = 0;
  constexpr std::span<const char* const> span() const { return {names.data(), size}; }
};
constexpr TableChannels table_channels(std::span<const TermWeight> weights, bool ibl) {
  TermValues used;  // 1 where weighed or needed
  used[Term::One] = 1;
  for (const auto& w : weights) used[w.term] = 1;
  if (ibl)
    for (const auto& t : kTermRegistry)
      if (used[t.term] != 0) used[t.dfg.less] = 1;
  TableChannels out;
  if (!ibl) out.names[out.size++] = lut_channel::kLtcMatrix;
  for (const auto& t : kTermRegistry)
    if (used[t.term] != 0) out.names[out.size++] = ibl ? t.dfg.channel : t.ltc.channel;
  return out;
}

// A model's shader code, written in GLSL; the emitter (analysis/shader) translates it to HLSL
// by renaming types and intrinsics (vecN → floatN, mix → lerp), so it keeps to the subset both
// languages share: no single-argument vector constructors, no vector ternaries.
struct ShaderHelper {
  const char* name;    // the function it defines, emitted once per program
  const char* source;  // the complete GLSL function
};
struct ShaderCode {
  // Functions the body calls (fresnel/exact_shader.h, or the unit's own).
  std::span<const ShaderHelper* const> helpers;
  // Body of vec3 fresnel_<name>(float cos_theta, <each per-channel parameter as vec3>,
  // <each shared parameter as float>). Empty for a pre-integrable model whose punctual function
  // the emitter writes from its table terms (Σ_t w_t·term_t at v·h). The IBL and area functions
  // of a pre-integrable model are always written from its table terms.
  const char* body = "";
};

// A model's handle: its position in the registry. Compare, copy, and look up its spec.
class Model {
 public:
  constexpr Model() = default;
  constexpr explicit Model(int index) : index_(index) {}
  constexpr int index() const { return index_; }
  friend constexpr bool operator==(Model a, Model b) { return a.index_ == b.index_; }

 private:
  int index_ = 0;
};

// One model, as the rest of the program sees it (built from the unit by the registry).
struct ModelSpec {
  Model model;
  const char* name;   // command-line / CSV name
  const char* label;  // for people
  std::vector<ParamSpec> channel_params;
  std::vector<ParamSpec> shared_params;
  PreIntegration pre_integration;
  ShaderCode shader;
  // Pre-integrable models: the table terms and their weights in GLSL (empty for the others).
  std::span<const TermWeight> term_weights;
  bool can_leave_unit_range;  // the curve can leave [0, 1] for some parameters (reported, not
                              // clamped)
  bool has_output_clamp;      // the kernel clamps its output; evaluate(..., unclamped) skips that
  bool identifiable;          // a fit from a nearby start recovers the parameters (UnitFeatures)

  // Evaluations over the flat parameter layout.
  color::Rgb (*evaluate)(double cos_theta, const double* params, bool unclamped);
  color::RgbT<float> (*evaluate_float)(float cos_theta, const float* params);
  void (*batch_float)(const float* params, const float* cos_theta, std::size_t n, float* out);
  void (*batch_double)(const double* params, const double* cos_theta, std::size_t n, double* out);
  // Pre-integrable models: channel c's table terms (nullptr for the others).
  TableTerms (*table_terms)(const double* params, int channel);
  // The closed form of the hemispherical average 2∫F(μ)μ dμ of channel c, where the unit has one
  // (nullptr: fresnel/average.h integrates the kernel).
  double (*closed_form_average)(const double* params, int channel);

  int per_channel() const { return static_cast<int>(channel_params.size()); }
  int param_count() const { return 3 * per_channel() + static_cast<int>(shared_params.size()); }
  std::vector<std::string> param_names() const;  // "f0_r", ..., "eta_rep"
  std::vector<ParamRange> bounds() const;        // fit boxes, flat layout
  std::vector<ParamRange> domain() const;        // kernel domains, flat layout
};

namespace detail {
// out[c·n + i] = M::channel(cos_theta[i], channel c's parameters, shared parameters). The
// parameters are copied to locals first, so the compiler knows the output cannot alias them and
// can vectorize the plain scalar kernel.
template <class M, class T>
void batch_channels(const T* params, const T* cos_theta, std::size_t n, T* out) {
  constexpr int kPer = static_cast<int>(M::kChannelParams.size());
  constexpr int kShared = static_cast<int>(M::kSharedParams.size());
  T shared[kShared + 1] = {};
  for (int k = 0; k < kShared; ++k) shared[k] = params[3 * kPer + k];
  for (int c = 0; c < 3; ++c) {
    T p[kPer] = {};
    for (int k = 0; k < kPer; ++k) p[k] = params[c * kPer + k];
    T* __restrict o = out + static_cast<std::size_t>(c) * n;
    for (std::size_t i = 0; i < n; ++i) o[i] = M::channel(cos_theta[i], p, shared);
  }
}
}  // namespace detail

// All three channels of unit M from the flat parameter vector, for any scalar (double, float,
// Ceres Jets).
template <class M, class T>
color::RgbT<T> evaluate_unit(T cos_theta, const T* params) {
  constexpr int kPer = static_cast<int>(M::kChannelParams.size());
  const T* shared = params + 3 * kPer;
  return {M::channel(cos_theta, params, shared), M::channel(cos_theta, params + kPer, shared),
          M::channel(cos_theta, params + 2 * kPer, shared)};
}

// A unit may split its channel at the angle (UnitFeatures::prepared_channel): prepare(p, shared)
// does the work that does not depend on it, channel_at(cos_theta, prepared) the rest, with the
// operations of channel() in its order, so the values are channel()'s bit for bit. A fit evaluating
// every angle at one parameter point then prepares each channel once. For a unit without the split,
// prepare_channel keeps the pointers and channel_at calls channel().
template <class T>
struct UnpreparedChannel {
  const T* p;
  const T* shared;
};
template <class M, class T>
concept PreparesChannel = M::kFeatures.prepared_channel;
template <class M, class T>
auto prepare_channel(const T* p, const T* shared) {
  if constexpr (PreparesChannel<M, T>)
    return M::prepare(p, shared);
  else
    return UnpreparedChannel<T>{p, shared};
}
template <class M, class T, class P>
T channel_at(T cos_theta, const P& prepared) {
  if constexpr (PreparesChannel<M, T>)
    return M::channel_at(cos_theta, prepared);
  else
    return M::channel(cos_theta, prepared.p, prepared.shared);
}

// Sizes of unit M's flat parameter vector.
template <class M>
constexpr int unit_param_count() {
  return 3 * static_cast<int>(M::kChannelParams.size()) + static_cast<int>(M::kSharedParams.size());
}

}  // namespace fl::fresnel
