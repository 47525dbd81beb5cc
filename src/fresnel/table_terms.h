#pragma once
// The terms the lookup tables pre-integrate, one entry each. A pre-integrable model writes its
// Fresnel term per channel as weights on them, F(μ) = Σ_t w_t·term_t(μ) with μ = v·h
// (TableTerms), so that under a table the lobe integrates to Σ_t w_t·∫term_t ρ cos. The DFG and
// LTC-moment integrators (analysis/lut), the tables' layouts and files (analysis/lut/lut_layout,
// jobs/lut_files), the `lut` command's help, the shader emitter, the error as rendered and the
// tests iterate over kTermRegistry: a new term is one entry here.
#include <array>
#include <cstddef>

#include "fresnel/basis.h"

namespace fl::fresnel {

enum class Term { One, Schlick, F82, B2, B3, B4 };
inline constexpr std::size_t kTermCount = 6;

// A term's value at μ, given m = 1 − μ and m⁵ (the integrators compute both once per sample).
using TermKernel = double (*)(double mu, double m, double m5);

struct TermSpec {
  Term term;
  const char* formula;  // for people
  TermKernel kernel;
  // The GLSL function float NAME(float mu) a shader evaluates the term with (nullptr: the term 1),
  // and its body, or else the term's polynomial in x = 2μ − 1 (kBasisPolyDegree + 1 coefficients,
  // evaluated by Horner's rule).
  const char* glsl_name;
  const char* glsl_body;
  const double* polynomial;
  // The split-sum DFG channel holding the term, its texture ("dfg", "dfg_2", ...: `lut dfg
  // --out F.exr` writes F.exr, F_2.exr, ...), its component there, and the term it is stored less
  // of (itself: none). The split sum stores 1 as the scale ∫(1 − (1 − μ)⁵) ρ cos beside the bias
  // ∫(1 − μ)⁵ ρ cos (Karis 2013), so its integral is the sum of the two channels.
  const char* dfg_channel;
  const char* dfg_texture;
  const char* dfg_component;
  Term dfg_less;
  // The integrand as the DFG files describe it ("integral <dfg_integrand>rho cos"), with
  // Fc = (1 - mu)^5 and mu = v.h.
  const char* dfg_integrand;
  // The LTC moment holding ∫term ρ cos (Hill's n_D, f_D and the F82 analogue), its texture beside
  // the LTC matrix ("ltc_2", "ltc_3", ...), its component there, its symbol and integrand in the
  // LTC files, and a note for the ltc_2 file's description.
  const char* ltc_channel;
  const char* ltc_texture;
  const char* ltc_component;
  const char* ltc_symbol;
  const char* ltc_integrand;
  const char* ltc_note;
};

namespace term_kernels {
// The existing terms' operations are in the order the tables were always computed in, so the
// tables stay bit for bit.
constexpr double one(double, double, double) {
  return 1.0;
}
constexpr double schlick(double, double, double m5) {
  return m5;
}
constexpr double f82(double mu, double m, double m5) {
  return mu * m5 * m;
}
template <int K>
double basis(double mu, double, double) {
  return basis_term(K, mu);
}
}  // namespace term_kernels

inline constexpr const char* kSchlickGlsl = R"(  float m = 1.0 - mu;
  float m2 = m * m;
  return m2 * m2 * m;
)";
inline constexpr const char* kF82Glsl = R"(  float m = 1.0 - mu;
  float m2 = m * m;
  return mu * (m2 * m2 * m2);
)";

inline constexpr std::array<TermSpec, kTermCount> kTermRegistry{{
    {Term::One, "1", term_kernels::one, nullptr, nullptr, nullptr, "dfg1", "dfg", "r",
     Term::Schlick, "(1 - Fc) ", "n_d", "ltc_2", "r", "n_D", "", ""},
    {Term::Schlick, "(1 − μ)⁵", term_kernels::schlick, "fl_term_schlick", kSchlickGlsl, nullptr,
     "dfg2", "dfg", "g", Term::Schlick, "Fc ", "f_d", "ltc_2", "g", "f_D", "(1 - <v,h>)^5 ", ""},
    {Term::F82, "μ(1 − μ)⁶", term_kernels::f82, "fl_term_f82", kF82Glsl, nullptr, "dfg_f82", "dfg",
     "b", Term::F82, "mu (1 - mu)^6 ", "l_d", "ltc_2", "b", "l_D", "<v,h> (1 - <v,h>)^6 ",
     " (the F82 moment)"},
    {Term::B2, "b2(μ)", term_kernels::basis<2>, "fl_term_b2", nullptr, kBasisPolyCentred[0],
     "dfg_b2", "dfg_2", "r", Term::B2, "b2(mu) ", "b2_d", "ltc_3", "r", "b2_D", "b2(<v,h>) ", ""},
    {Term::B3, "b3(μ)", term_kernels::basis<3>, "fl_term_b3", nullptr, kBasisPolyCentred[1],
     "dfg_b3", "dfg_2", "g", Term::B3, "b3(mu) ", "b3_d", "ltc_3", "g", "b3_D", "b3(<v,h>) ", ""},
    {Term::B4, "b4(μ)", term_kernels::basis<4>, "fl_term_b4", nullptr, kBasisPolyCentred[2],
     "dfg_b4", "dfg_2", "b", Term::B4, "b4(mu) ", "b4_d", "ltc_3", "b", "b4_D", "b4(<v,h>) ", ""},
}};

constexpr std::size_t term_index(Term t) {
  return static_cast<std::size_t>(t);
}
constexpr const TermSpec& term_spec(Term t) {
  return kTermRegistry[term_index(t)];
}

// term(μ), given m = 1 − μ and m⁵.
inline double term_kernel(Term t, double mu, double m, double m5) {
  return term_spec(t).kernel(mu, m, m5);
}
// What the term's DFG channel integrates: the term, less its dfg_less term.
inline double dfg_kernel(Term t, double mu, double m, double m5) {
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
