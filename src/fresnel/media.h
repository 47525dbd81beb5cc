#pragma once
// Fresnel approximations across media other than air: F0 re-expressed against an outside medium,
// and Schlick for internal reflection.
#include <algorithm>
#include <cmath>

#include "fresnel/models/schlick.h"

namespace fl::fresnel {

// Hoffman 2020, external media: F0 of a dielectric re-expressed against a medium of index eta_e;
// exact for dielectrics at normal incidence.
inline double f0_in_medium_symmetric(double f0, double eta_e) {
  const double s0e = (eta_e - 1.0) / (eta_e + 1.0);
  const double s0 = std::sqrt(std::max(0.0, f0));
  const double r = (s0 - s0e) / (1.0 - s0 * s0e);
  return r * r;
}

// Derived here (not from a paper): a metal variant of the external-media adjustment, not
// symmetric in F0 and the medium. The metal is taken to have real index 1 and κ² = 4·F0/(1 − F0)
// (which gives F0 in air), so in a medium of index η_E:
// F0′ = ((1 − η_E)²(1 − F0) + 4F0) / ((1 + η_E)²(1 − F0) + 4F0).
inline double f0_in_medium_metal(double f0, double eta_e) {
  const double a = (1.0 - eta_e) * (1.0 - eta_e), b = (1.0 + eta_e) * (1.0 + eta_e);
  const double one_minus = std::max(0.0, 1.0 - f0);
  return (a * one_minus + 4.0 * f0) / (b * one_minus + 4.0 * f0);
}

// The real index whose normal-incidence reflectance ((η − 1)/(η + 1))² is f0: η = (1 + √f0)/(1 −
// √f0), with f0 held below 1 so that η stays finite.
inline double ior_from_f0(double f0) {
  const double s = std::sqrt(std::clamp(f0, 0.0, 0.999999));
  return (1.0 + s) / (1.0 - s);
}

// Hoffman 2020, Schlick 1994 for internal reflection: evaluated with the transmission angle's
// cosine for a dielectric of index n = (1 + √F0)/(1 − √F0) seen from inside; 1 past the critical
// angle.
inline double schlick_internal(double cos_theta_i, double f0) {
  const double n = ior_from_f0(f0);
  const double sin2_t = n * n * (1.0 - cos_theta_i * cos_theta_i);
  if (sin2_t >= 1.0) return 1.0;
  return schlick(std::sqrt(1.0 - sin2_t), f0);
}

}  // namespace fl::fresnel
