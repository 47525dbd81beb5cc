#pragma once
// Exact unpolarized Fresnel reflectance. Ground truth is evaluated in double; the functions are
// templated so fits can differentiate the RGB Fresnel-equation models.
#include <algorithm>
#include <cmath>
#include <complex>

#include "color/autodiff.h"

namespace fl::fresnel {

template <class T>
struct Polarized {
  T r_s{}, r_p{};  // s- and p-polarized reflectance
  T unpolarized() const { return T(0.5) * (r_s + r_p); }
};

// Born & Wolf, Principles of Optics §14.2: conductor Fresnel equations for a relative complex
// index eta + i·kappa (both relative to the outside medium), in the a/b form (as in Mitsuba's
// fresnelConductorExact):
// a² + b² = sqrt((η² − κ² − sin²θ)² + 4η²κ²), a² = (a² + b² + η² − κ² − sin²θ)/2.
// Valid for κ = 0 as well, including η < 1 past the critical angle (total internal reflection).
template <class T>
Polarized<T> fresnel_conductor_polarized(T cos_theta_i, T eta, T kappa) {
  using color::safe_sqrt;
  // An index-matched interface (η = 1, κ = 0) is no interface: nothing is reflected, at any angle.
  if (eta == T(1.0) && kappa == T(0.0)) return {T(0.0), T(0.0)};
  if (cos_theta_i > T(1.0)) cos_theta_i = T(1.0);
  if (cos_theta_i < T(0.0)) cos_theta_i = T(0.0);
  const T c2 = cos_theta_i * cos_theta_i;
  const T s2 = T(1.0) - c2;
  const T t0 = eta * eta - kappa * kappa - s2;
  const T a2pb2 = safe_sqrt(t0 * t0 + T(4.0) * eta * eta * kappa * kappa);
  // a² = (a² + b² + t0)/2 cancels when t0 < 0 (η < 1 or κ > η near and past the critical
  // angle); there the equal form 2η²κ²/(a² + b² − t0) keeps float precision.
  T a2 = t0 >= T(0.0) ? T(0.5) * (a2pb2 + t0) : T(2.0) * eta * eta * kappa * kappa / (a2pb2 - t0);
  if (a2 < T(0.0)) a2 = T(0.0);
  const T a = safe_sqrt(a2);
  const T t1 = a2pb2 + c2;
  const T t2 = T(2.0) * a * cos_theta_i;
  const T r_s = (t1 - t2) / (t1 + t2);
  const T t3 = a2pb2 * c2 + s2 * s2;
  const T t4 = t2 * s2;
  // At grazing incidence both polarizations reflect fully; t3 + t4 → 0 only when a2pb2 = 0.
  const T den = t3 + t4;
  const T r_p = den > T(0.0) ? r_s * (t3 - t4) / den : T(1.0);
  return {r_s, r_p};
}

template <class T>
T fresnel_conductor(T cos_theta_i, T eta, T kappa) {
  return fresnel_conductor_polarized(cos_theta_i, eta, kappa).unpolarized();
}

// Conductor reflectance for a complex index relative to the outside medium.
inline double fresnel_conductor(double cos_theta_i, std::complex<double> eta) {
  return fresnel_conductor<double>(cos_theta_i, eta.real(), eta.imag());
}

// Born & Wolf, Principles of Optics §1.5.2: dielectric Fresnel equations for the real relative
// index eta = η_t/η_i (Snell's law; total internal reflection when eta < 1 past the critical
// angle).
template <class T>
Polarized<T> fresnel_dielectric_polarized(T cos_theta_i, T eta) {
  using std::sqrt;
  if (eta == T(1.0)) return {T(0.0), T(0.0)};  // no interface
  if (cos_theta_i > T(1.0)) cos_theta_i = T(1.0);
  if (cos_theta_i < T(0.0)) cos_theta_i = T(0.0);
  const T sin2_t = (T(1.0) - cos_theta_i * cos_theta_i) / (eta * eta);
  if (sin2_t >= T(1.0)) return {T(1.0), T(1.0)};
  const T cos_t = sqrt(T(1.0) - sin2_t);
  const T rs = (cos_theta_i - eta * cos_t) / (cos_theta_i + eta * cos_t);
  const T rp = (eta * cos_theta_i - cos_t) / (eta * cos_theta_i + cos_t);
  return {rs * rs, rp * rp};
}

template <class T>
T fresnel_dielectric(T cos_theta_i, T eta) {
  return fresnel_dielectric_polarized(cos_theta_i, eta).unpolarized();
}

// Snell's law: cosine of the refracted angle for relative index eta (0 past the critical angle).
inline double cos_transmitted(double cos_theta_i, double eta) {
  const double sin2_t = (1.0 - cos_theta_i * cos_theta_i) / (eta * eta);
  return sin2_t >= 1.0 ? 0.0 : std::sqrt(1.0 - sin2_t);
}

}  // namespace fl::fresnel
