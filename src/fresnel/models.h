#pragma once
// Fresnel approximations (SPEC §2), pure scalar kernels templated on T so Ceres can
// differentiate them. RGB models apply them per channel.
#include <cmath>

#include "fresnel/exact.h"

namespace fl::fresnel {

// Schlick 1994.
template <class T>
T schlick(T cos_theta, T f0) {
  // T(1.0), not 1.0: in float a double constant would promote the arithmetic to double.
  const T m = T(1.0) - cos_theta;
  const T m2 = m * m;
  return f0 + (T(1.0) - f0) * (m2 * m2 * m);
}

// Generalized Schlick (as in OpenPBR / MaterialX generalized_schlick_bsdf): F0, F90, exponent p.
template <class T>
T generalized_schlick(T cos_theta, T f0, T f90, T p) {
  using std::pow;
  const T m = 1.0 - cos_theta;
  if (m <= T(0.0)) return f0;
  return f0 + (f90 - f0) * pow(m, p);
}

// Lazányi & Szirmay-Kalos 2005: Schlick minus a·cosθ·(1 − cosθ)^α.
template <class T>
T lazanyi(T cos_theta, T f0, T a, T alpha) {
  using std::pow;
  const T m = 1.0 - cos_theta;
  if (m <= T(0.0)) return f0;
  return schlick(cos_theta, f0) - a * cos_theta * pow(m, alpha);
}

// Hoffman 2019, the F82 model: Lazányi with α = 6 and a chosen so that the curve passes through
// F82 at cosθ = 1/7. 823543/46656 = 7⁷/6⁶ = 1/(c(1 − c)⁶) and 49/6 = (1 − c)⁵/(c(1 − c)⁶) at c = 1/7.
template <class T>
T f82_coefficient(T f0, T f82) {
  return T(823543.0 / 46656.0) * (f0 - f82) + T(49.0 / 6.0) * (T(1.0) - f0);
}
template <class T>
T hoffman_f82_unclamped(T cos_theta, T f0, T f82) {
  const T m = T(1.0) - cos_theta;
  const T m2 = m * m;
  return schlick(cos_theta, f0) - f82_coefficient(f0, f82) * cos_theta * (m2 * m2 * m2);
}
template <class T>
T hoffman_f82(T cos_theta, T f0, T f82) {
  const T f = hoffman_f82_unclamped(cos_theta, f0, f82);
  if (f < T(0.0)) return T(0.0);
  if (f > T(1.0)) return T(1.0);
  return f;
}

// Gulbrandsen 2014, "Artist Friendly Metallic Fresnel": F0 (r) and edge tint (g) → η, κ.
// r is clamped below 1 (the mapping is singular at r = 1) and above 0.
constexpr double kGulbrandsenMaxR = 0.99999;
template <class T>
T gulbrandsen_clamp_r(T r) {
  if (r > T(kGulbrandsenMaxR)) return T(kGulbrandsenMaxR);
  if (r < T(1e-9)) return T(1e-9);
  return r;
}
template <class T>
T gulbrandsen_n_min(T r) { return (1.0 - r) / (1.0 + r); }
template <class T>
T gulbrandsen_n_max(T r) {
  using std::sqrt;
  const T s = sqrt(r);
  return (1.0 + s) / (1.0 - s);
}
template <class T>
T gulbrandsen_eta(T r, T g) {
  r = gulbrandsen_clamp_r(r);
  return g * gulbrandsen_n_min(r) + (1.0 - g) * gulbrandsen_n_max(r);
}
template <class T>
T gulbrandsen_kappa(T r, T eta) {
  using color::detail::safe_sqrt;
  r = gulbrandsen_clamp_r(r);
  const T num = r * (eta + 1.0) * (eta + 1.0) - (eta - 1.0) * (eta - 1.0);
  return safe_sqrt(num / (1.0 - r));
}
// Gulbrandsen 2014, inverted: the edge tint g that gives index eta at reflectance r (η is linear
// in g between n_max at g = 0 and n_min at g = 1).
template <class T>
T gulbrandsen_g(T r, T eta) {
  r = gulbrandsen_clamp_r(r);
  const T n_min = gulbrandsen_n_min(r), n_max = gulbrandsen_n_max(r);
  return (n_max - eta) / (n_max - n_min);
}
template <class T>
T gulbrandsen(T cos_theta, T f0, T g) {
  const T eta = gulbrandsen_eta(f0, g);
  return fresnel_conductor(cos_theta, eta, gulbrandsen_kappa(f0, eta));
}

// Cook & Torrance 1982 colour interpolation in the talk's modified form: the scalar Fresnel
// curve F′ of one representative index shapes the colour change from F0 to 1.
template <class T>
T cook_torrance(T cos_theta, T f0, T eta_rep, T kappa_rep) {
  const T fp = fresnel_conductor(cos_theta, eta_rep, kappa_rep);
  const T fp0 = fresnel_conductor(T(1.0), eta_rep, kappa_rep);
  T t = (fp - fp0) / (1.0 - fp0);
  if (t < T(0.0)) t = T(0.0);
  return f0 + (1.0 - f0) * t;
}

// Hoffman 2020 (SPEC §2), external media: F0 of a dielectric re-expressed against a medium of
// index eta_e; exact for dielectrics at normal incidence.
inline double f0_in_medium_symmetric(double f0, double eta_e) {
  const double s0e = (eta_e - 1.0) / (eta_e + 1.0);
  const double s0 = std::sqrt(std::max(0.0, f0));
  const double r = (s0 - s0e) / (1.0 - s0 * s0e);
  return r * r;
}

}  // namespace fl::fresnel

namespace fl::fresnel {

// Derived here (not from a paper): a metal variant of the external-media adjustment, not
// symmetric in F0 and the medium. The metal is taken to have real index 1 and κ² = 4·F0/(1 − F0) (which gives F0 in air), so in a
// medium of index η_E: F0′ = ((1 − η_E)²(1 − F0) + 4F0) / ((1 + η_E)²(1 − F0) + 4F0).
inline double f0_in_medium_metal(double f0, double eta_e) {
  const double a = (1.0 - eta_e) * (1.0 - eta_e), b = (1.0 + eta_e) * (1.0 + eta_e);
  const double one_minus = std::max(0.0, 1.0 - f0);
  return (a * one_minus + 4.0 * f0) / (b * one_minus + 4.0 * f0);
}

// Schlick 1994 for internal reflection (SPEC §2, Hoffman 2020): evaluated with the transmission angle's cosine for a
// dielectric of index n = (1 + √F0)/(1 − √F0) seen from inside; 1 past the critical angle.
inline double schlick_internal(double cos_theta_i, double f0) {
  const double s = std::sqrt(std::clamp(f0, 0.0, 0.999999));
  const double n = (1.0 + s) / (1.0 - s);
  const double sin2_t = n * n * (1.0 - cos_theta_i * cos_theta_i);
  if (sin2_t >= 1.0) return 1.0;
  return schlick(std::sqrt(1.0 - sin2_t), f0);
}

}  // namespace fl::fresnel
