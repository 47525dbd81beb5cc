#pragma once
// The least-squares normal equations G·c = y of a few functions, solved by Cholesky (G = L·Lᵀ).
#include <array>
#include <cmath>
#include <cstddef>

namespace fl::fresnel {

// Solves G·c = y for the symmetric positive definite leading n × n block of g (its lower triangle
// read, then overwritten by L; y overwritten by L⁻¹·y); the entries of c past n are 0.
template <std::size_t N>
std::array<double, N> solve_normal_equations(double (&g)[N][N], double (&y)[N], std::size_t n) {
  for (std::size_t a = 0; a < n; ++a)  // G = L·Lᵀ, L in the lower triangle
    for (std::size_t c = 0; c <= a; ++c) {
      double s = g[a][c];
      for (std::size_t k = 0; k < c; ++k) s -= g[a][k] * g[c][k];
      g[a][c] = a == c ? std::sqrt(s) : s / g[c][c];
    }
  for (std::size_t a = 0; a < n; ++a) {  // L·z = y
    for (std::size_t k = 0; k < a; ++k) y[a] -= g[a][k] * y[k];
    y[a] /= g[a][a];
  }
  std::array<double, N> c{};
  for (std::size_t a = n; a-- > 0;) {  // Lᵀ·c = z
    double s = y[a];
    for (std::size_t k = a + 1; k < n; ++k) s -= g[k][a] * c[k];
    c[a] = s / g[a][a];
  }
  return c;
}

}  // namespace fl::fresnel
