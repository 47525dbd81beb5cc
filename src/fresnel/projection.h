#pragma once
// A curve projected on the tables' terms: the least-squares weights that make any Fresnel curve
// pre-integrable, F(μ) ≈ Σ_t w_t·term_t(μ) (table_terms.h), per channel.
#include <cmath>
#include <span>
#include <vector>

#include "fresnel/normal_equations.h"
#include "fresnel/table_terms.h"

namespace fl::fresnel {

// Hoffman's span {1, (1 − μ)⁵, μ(1 − μ)⁶} and the 5-term Fresnel basis {1, b1, b2, b3, b4}.
inline constexpr Term kHoffmanSpan[] = {Term::One, Term::Schlick, Term::F82};
inline constexpr Term kBasisSpan[] = {Term::One, Term::B1, Term::B2, Term::B3, Term::B4};

// Least-squares weights of f(μ_j) on `terms` (every other term 0): the normal equations solved by
// Cholesky. The terms must be linearly independent over the μ_j.
inline TableTerms project_on_terms(std::span<const double> mu, std::span<const double> f,
                                   std::span<const Term> terms) {
  const size_t n = terms.size();
  double g[kTermCount][kTermCount] = {}, y[kTermCount] = {};
  for (size_t j = 0; j < mu.size(); ++j) {
    const double m = 1.0 - mu[j], m5 = m * m * m * m * m;
    double b[kTermCount];
    for (size_t a = 0; a < n; ++a) b[a] = term_kernel(terms[a], mu[j], m, m5);
    for (size_t a = 0; a < n; ++a) {
      y[a] += b[a] * f[j];
      for (size_t c = 0; c <= a; ++c) g[a][c] += b[a] * b[c];
    }
  }
  const auto c = solve_normal_equations(g, y, n);
  TableTerms w;
  for (size_t a = 0; a < n; ++a) w[terms[a]] = c[a];
  return w;
}

}  // namespace fl::fresnel
