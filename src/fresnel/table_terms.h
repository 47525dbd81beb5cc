#pragma once
// The terms the lookup tables pre-integrate, one entry each. A pre-integrable model writes its
// Fresnel term per channel as weights on them, F(μ) = Σ_t w_t·term_t(μ) with μ = v·h
// (TableTerms), so that under a table the lobe integrates to Σ_t w_t·∫term_t ρ cos. The DFG and
// LTC-moment integrators (analysis/lut), the tables' layouts and files (analysis/lut/lut_layout,
// jobs/lut_files), the shader emitter, the error as rendered and the tests iterate over
// kTermRegistry: a new term is one entry here (and its kernel in term_kernel).
#include <array>
#include <cstddef>

namespace fl::fresnel {

enum class Term { One, Schlick, F82 };
inline constexpr std::size_t kTermCount = 3;

struct TermSpec {
  Term term;
  const char* formula;  // for people
  // The split-sum DFG channel holding the term, its texture component in the DFG table, and the
  // term it is stored less of (Term::One itself: none). The split sum stores 1 as the scale
  // ∫(1 − (1 − μ)⁵) ρ cos beside the bias ∫(1 − μ)⁵ ρ cos (Karis 2013), so its integral is the
  // sum of the two channels.
  const char* dfg_channel;
  const char* dfg_component;
  Term dfg_less;
  // The LTC moment holding ∫term ρ cos (Hill's n_D, f_D and the F82 analogue) and its component in
  // the ltc_2 texture.
  const char* ltc_channel;
  const char* ltc_component;
};

inline constexpr std::array<TermSpec, kTermCount> kTermRegistry{{
    {Term::One, "1", "dfg1", "r", Term::Schlick, "n_d", "r"},
    {Term::Schlick, "(1 − μ)⁵", "dfg2", "g", Term::Schlick, "f_d", "g"},
    {Term::F82, "μ(1 − μ)⁶", "dfg_f82", "b", Term::F82, "l_d", "b"},
}};

constexpr std::size_t term_index(Term t) {
  return static_cast<std::size_t>(t);
}
constexpr const TermSpec& term_spec(Term t) {
  return kTermRegistry[term_index(t)];
}

// term(μ), given m = 1 − μ and m⁵ (the integrators compute both once per sample; the operations
// are in the order the tables were always computed in, so the tables stay bit for bit).
constexpr double term_kernel(Term t, double mu, double m, double m5) {
  switch (t) {
    case Term::One:
      return 1.0;
    case Term::Schlick:
      return m5;
    case Term::F82:
      return mu * m5 * m;
  }
  return 0.0;
}
// What the term's DFG channel integrates: the term, less its dfg_less term.
constexpr double dfg_kernel(Term t, double mu, double m, double m5) {
  const Term less = term_spec(t).dfg_less;
  if (less == t) return term_kernel(t, mu, m, m5);
  return term_kernel(t, mu, m, m5) - term_kernel(less, mu, m, m5);
}

// Per-term values: a model's weights, a table cell's channels or integrals.
struct TermValues {
  std::array<double, kTermCount> v{};
  double& operator[](Term t) { return v[term_index(t)]; }
  double operator[](Term t) const { return v[term_index(t)]; }
};

// A channel's Fresnel term as weights on the tables' terms (0 for a term it does not use).
using TableTerms = TermValues;

// The lobe's integral of each term from a DFG texel's channels: the channel, plus the channel of
// the term it is stored less of.
inline TermValues dfg_term_integrals(const TermValues& dfg) {
  TermValues out;
  for (const auto& t : kTermRegistry)
    out[t.term] = t.dfg_less == t.term ? dfg[t.term] : dfg[t.term] + dfg[t.dfg_less];
  return out;
}

}  // namespace fl::fresnel
