#pragma once
// The DFG and LTC moment integrals of the GGX lobe by Gauss–Legendre quadrature, from the lobe
// written independently of src/ (ggx_reference.h): the tests' reference for the lookup tables.
#include <cmath>
#include <numbers>

#include "ggx_reference.h"
#include "quadrature.h"

namespace fl::test {

struct Reference {
  double n_d = 0, f_d = 0, l_d = 0, dfg1 = 0, dfg2 = 0;
};

// ∫ g(v·h) f (n·l) dl over l with n·l > 0, written over half vectors h = (θ, φ):
// dl = 4 (v·h) dω_h, so f (n·l) dl = D G₂ (v·h)/(n·v) dω_h. n·l > 0 ⇔ cos φ > c(θ) =
// −(cos θ_v / sin θ_v) cot 2θ, which is −1 at θ₁ = (π/2 − θ_v)/2 and +1 at θ₂ = (π/2 + θ_v)/2;
// the φ-range is integrated exactly (Gauss–Legendre panels, no sampling).
// The lobe integrals of up to four functions of v·h at once: terms(voh) gives their values.
template <class Terms>
Values reference_lobe_integrals(double nov, double alpha, Terms terms) {
  constexpr double kPi = std::numbers::pi;
  static const GaussRule g_theta = gauss_legendre(16), g_phi = gauss_legendre(32);
  const double theta_v = std::acos(nov), sin_v = std::sin(theta_v);
  const double theta1 = 0.5 * (kPi / 2 - theta_v), theta2 = 0.5 * (kPi / 2 + theta_v);
  auto f_theta = [&](double theta) -> Values {
    const double ct = std::cos(theta), st = std::sin(theta);
    double phi_max = kPi;
    if (sin_v > 0) {
      const double c = -(nov / sin_v) * std::cos(2 * theta) / std::sin(2 * theta);
      phi_max = c <= -1 ? kPi : (c >= 1 ? 0 : std::acos(c));
    } else if (theta >= kPi / 4) {
      phi_max = 0;
    }
    if (phi_max <= 0) return Values{};
    const double d = ggx_ref::ndf(ct, alpha);
    auto f_phi = [&](double phi) -> Values {
      const double voh = sin_v * st * std::cos(phi) + nov * ct;
      const double nol = 2 * voh * ct - nov;
      if (nol <= 0 || voh <= 0) return Values{};
      const double w = d * ggx_ref::g2(nov, nol, alpha) * voh / nov;
      return w * terms(voh);
    };
    return (2 * st) * integrate_panel<Values>(f_phi, 0, phi_max, g_phi);
  };
  return integrate_theta<Values>(f_theta, theta2, alpha, {theta1}, g_theta);
}

inline Reference reference_moments(double nov, double alpha) {
  const Values v = reference_lobe_integrals(nov, alpha, [](double voh) -> Values {
    const double m = 1 - voh, m5 = m * m * m * m * m;
    return {1.0, m5, voh * m5 * m, 1 - m5};
  });
  return {v[0], v[1], v[2], v[3], v[1]};
}

}  // namespace fl::test
