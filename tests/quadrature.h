#pragma once
// Deterministic quadrature for the tests' independent references: Gauss–Legendre rules on
// panels (no sampling, nothing shared with the quasi-Monte Carlo estimators under test).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace fl::test {

struct GaussRule {
  std::vector<double> x, w;  // nodes and weights on [-1, 1]
};

// Abramowitz & Stegun 25.4.29: the nodes are the roots of P_n (Newton's method on the three-term
// recurrence), the weights 2 / ((1 − x²) P_n'(x)²).
inline GaussRule gauss_legendre(int n) {
  GaussRule r;
  r.x.resize(n);
  r.w.resize(n);
  auto legendre = [n](double x, double& p, double& dp) {
    double p0 = 1, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    p = p1;
    dp = n * (x * p1 - p0) / (x * x - 1);
  };
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), p = 0, dp = 1;
    for (int it = 0; it < 100; ++it) {
      legendre(x, p, dp);
      const double dx = p / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    legendre(x, p, dp);
    r.x[i] = x;
    r.w[i] = 2 / ((1 - x * x) * dp * dp);
  }
  return r;
}

// Several integrands at once.
using Values = std::array<double, 4>;
inline Values operator+(Values a, const Values& b) {
  for (int k = 0; k < 4; ++k) a[k] += b[k];
  return a;
}
inline Values operator*(double s, Values a) {
  for (auto& x : a) x *= s;
  return a;
}

// ∫_a^b f with the substitution t = a + (b − a)(1 − cos πs)/2, which removes square-root
// endpoint singularities, then Gauss–Legendre in s.
template <class V = double, class F>
V integrate_panel(const F& f, double a, double b, const GaussRule& g) {
  constexpr double kPi = std::numbers::pi;
  V s{};
  for (size_t k = 0; k < g.x.size(); ++k) {
    const double u = 0.5 * (g.x[k] + 1);
    const double t = a + (b - a) * 0.5 * (1 - std::cos(kPi * u));
    const double dt = (b - a) * 0.5 * kPi * std::sin(kPi * u) * 0.5;
    s = s + (g.w[k] * dt) * f(t);
  }
  return s;
}

// Panels on [0, end]: the given breakpoints, geometric steps from α/16 (where a GGX lobe of
// width α varies), and at most 0.1 rad.
template <class V = double, class F>
V integrate_theta(const F& f, double end, double alpha, std::vector<double> breaks,
                  const GaussRule& g) {
  for (double t = alpha / 16; t < end; t *= 2) breaks.push_back(t);
  for (double t = 0.1; t < end; t += 0.1) breaks.push_back(t);
  breaks.push_back(0);
  breaks.push_back(end);
  std::sort(breaks.begin(), breaks.end());
  V s{};
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = std::clamp(breaks[k], 0.0, end), b = std::clamp(breaks[k + 1], 0.0, end);
    if (b > a) s = s + integrate_panel<V>(f, a, b, g);
  }
  return s;
}

// ∫ f(x, y, z) dω over the unit sphere's directions with polar angle θ ≤ theta_end from +Z,
// panels in θ (refined near θ = 0 at the scale `alpha`), two panels in φ.
inline double integrate_sphere(const std::function<double(double, double, double)>& f,
                               double theta_end, double alpha = 0.05) {
  static const GaussRule g_theta = gauss_legendre(16), g_phi = gauss_legendre(48);
  return integrate_theta(
      [&](double t) {
        const double st = std::sin(t), ct = std::cos(t);
        double s = 0;
        for (int half = 0; half < 2; ++half)
          s += integrate_panel(
              [&](double phi) { return f(st * std::cos(phi), st * std::sin(phi), ct); },
              half * std::numbers::pi, (half + 1) * std::numbers::pi, g_phi);
        return s * st;
      },
      theta_end, alpha, {}, g_theta);
}

// ∫ f(ω) dω over the hemisphere ω·axis ≥ 0 (axis a unit vector in the xz-plane), in polar
// coordinates about the axis, so a density whose support is that hemisphere has its edge on a panel
// boundary.
inline double integrate_hemisphere_about(double axis_x, double axis_z,
                                         const std::function<double(double, double, double)>& f,
                                         double alpha = 0.05) {
  // The frame (X, Y, A) with X = Y × A: a point (x, y, z) of it is x X + y Y + z A.
  return integrate_sphere(
      [&](double x, double y, double z) {
        return f(x * axis_z + z * axis_x, y, -x * axis_x + z * axis_z);
      },
      std::numbers::pi / 2, alpha);
}

}  // namespace fl::test
