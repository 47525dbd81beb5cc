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

enum class Term { One, Schlick, F82, B1, B2, B3, B4 };
inline constexpr std::size_t kTermCount = 7;

// A term's value at μ, given m = 1 − μ and m⁵ (the integrators compute both once per sample).
using TermKernel = double (*)(double mu, double m, double m5);

// How a shader evaluates the term: the GLSL function float NAME(float mu) (nullptr: the term 1),
// with its body, or else the term's polynomial in x = 2μ − 1 (kBasisPolyDegree + 1 coefficients,
// evaluated by Horner's rule).
struct TermGlsl {
  const char* name = nullptr;
  const char* body = nullptr;
  const double* polynomial = nullptr;
};
// The split-sum DFG channel holding the term, its texture ("dfg", "dfg_2", ...: `lut dfg --out
// F.exr` writes F.exr, F_2.exr, ...), its component there, and the term it is stored less of
// (itself: none). The split sum stores 1 as the scale ∫(1 − (1 − μ)⁵) ρ cos beside the bias
// ∫(1 − μ)⁵ ρ cos (Karis 2013), so its integral is the sum of the two channels. `integrand`: as
// the DFG files describe it ("integral <integrand>rho cos"), with Fc = (1 - mu)^5 and mu = v.h.
struct TermDfg {
  const char* channel;
  const char* texture;
  const char* component;
  Term less;
  const char* integrand;
};
// The LTC moment holding ∫term ρ cos (Hill's n_D, f_D and the F82 analogue), its texture beside
// the LTC matrix ("ltc_2", "ltc_3", ...), its component there, its symbol and integrand in the LTC
// files, and a note for the ltc_2 file's description.
struct TermLtc {
  const char* channel;
  const char* texture;
  const char* component;
  const char* symbol;
  const char* integrand;
  const char* note = "";
};
struct TermSpec {
  Term term;
  const char* formula;  // for people
  TermKernel kernel;
  TermGlsl glsl;
  TermDfg dfg;
  TermLtc ltc;
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
    {.term = Term::One,
     .formula = "1",
     .kernel = term_kernels::one,
     .glsl = {},
     .dfg = {.channel = "dfg1",
             .texture = "dfg",
             .component = "r",
             .less = Term::Schlick,
             .integrand = "(1 - Fc) "},
     .ltc = {.channel = "n_d",
             .texture = "ltc_2",
             .component = "r",
             .symbol = "n_D",
             .integrand = ""}},
    {.term = Term::Schlick,
     .formula = "(1 − μ)⁵",
     .kernel = term_kernels::schlick,
     .glsl = {.name = "fl_term_schlick", .body = kSchlickGlsl},
     .dfg = {.channel = "dfg2",
             .texture = "dfg",
             .component = "g",
             .less = Term::Schlick,
             .integrand = "Fc "},
     .ltc = {.channel = "f_d",
             .texture = "ltc_2",
             .component = "g",
             .symbol = "f_D",
             .integrand = "(1 - <v,h>)^5 "}},
    {.term = Term::F82,
     .formula = "μ(1 − μ)⁶",
     .kernel = term_kernels::f82,
     .glsl = {.name = "fl_term_f82", .body = kF82Glsl},
     .dfg = {.channel = "dfg_f82",
             .texture = "dfg",
             .component = "b",
             .less = Term::F82,
             .integrand = "mu (1 - mu)^6 "},
     .ltc = {.channel = "l_d",
             .texture = "ltc_2",
             .component = "b",
             .symbol = "l_D",
             .integrand = "<v,h> (1 - <v,h>)^6 ",
             .note = " (the F82 moment)"}},
    {.term = Term::B1,
     .formula = "b1(μ)",
     .kernel = term_kernels::basis<1>,
     .glsl = {.name = "fl_term_b1", .polynomial = kBasisPolyCentred[0]},
     .dfg = {.channel = "dfg_b1",
             .texture = "dfg_2",
             .component = "r",
             .less = Term::B1,
             .integrand = "b1(mu) "},
     .ltc = {.channel = "b1_d",
             .texture = "ltc_3",
             .component = "r",
             .symbol = "b1_D",
             .integrand = "b1(<v,h>) "}},
    {.term = Term::B2,
     .formula = "b2(μ)",
     .kernel = term_kernels::basis<2>,
     .glsl = {.name = "fl_term_b2", .polynomial = kBasisPolyCentred[1]},
     .dfg = {.channel = "dfg_b2",
             .texture = "dfg_2",
             .component = "g",
             .less = Term::B2,
             .integrand = "b2(mu) "},
     .ltc = {.channel = "b2_d",
             .texture = "ltc_3",
             .component = "g",
             .symbol = "b2_D",
             .integrand = "b2(<v,h>) "}},
    {.term = Term::B3,
     .formula = "b3(μ)",
     .kernel = term_kernels::basis<3>,
     .glsl = {.name = "fl_term_b3", .polynomial = kBasisPolyCentred[2]},
     .dfg = {.channel = "dfg_b3",
             .texture = "dfg_2",
             .component = "b",
             .less = Term::B3,
             .integrand = "b3(mu) "},
     .ltc = {.channel = "b3_d",
             .texture = "ltc_3",
             .component = "b",
             .symbol = "b3_D",
             .integrand = "b3(<v,h>) "}},
    {.term = Term::B4,
     .formula = "b4(μ)",
     .kernel = term_kernels::basis<4>,
     .glsl = {.name = "fl_term_b4", .polynomial = kBasisPolyCentred[3]},
     .dfg = {.channel = "dfg_b4",
             .texture = "dfg_2",
             .component = "a",
             .less = Term::B4,
             .integrand = "b4(mu) "},
     .ltc = {.channel = "b4_d",
             .texture = "ltc_3",
             .component = "a",
             .symbol = "b4_D",
             .integrand = "b4(<v,h>) "}},
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
  const Term less = term_spec(t).dfg.less;
  if (less == t) return term_kernel(t, mu, m, m5);
  return term_kernel(t, mu, m, m5) - term_kernel(less, mu, m, m5);
}

// Per-term values: a model's weights, a table cell's channels or integrals.
struct TermValues {
  std::array<double, kTermCount> v{};
  constexpr double& operator[](Term t) { return v[term_index(t)]; }
  constexpr double operator[](Term t) const { return v[term_index(t)]; }
};

// A channel's Fresnel term as weights on the tables' terms (0 for a term it does not use).
using TableTerms = TermValues;

// The lobe's integral of each term from a DFG texel's channels: the channel, plus the channel of
// the term it is stored less of.
inline TermValues dfg_term_integrals(const TermValues& dfg) {
  TermValues out;
  for (const auto& t : kTermRegistry)
    out[t.term] = t.dfg.less == t.term ? dfg[t.term] : dfg[t.term] + dfg[t.dfg.less];
  return out;
}

}  // namespace fl::fresnel
