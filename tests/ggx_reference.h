#pragma once
// The GGX lobe and the LTC density written independently of src/ (brdf/ggx.h,
// analysis/ltc/ltc_fit.h), from the papers' own forms, for the tests' references. Only the vector
// type is shared.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "brdf/ggx.h"

namespace fl::test::ggx_ref {

constexpr double kPi = std::numbers::pi;

// Walter et al. 2007, eq. 33: D(h) = 1 / (π α² cos⁴θ_h (1 + tan²θ_h / α²)²).
inline double ndf(double cos_h, double alpha) {
  const double c2 = cos_h * cos_h, tan2 = (1 - c2) / c2;
  const double q = 1 + tan2 / (alpha * alpha);
  return 1 / (kPi * alpha * alpha * c2 * c2 * q * q);
}
// Heitz 2014, eq. 72: Smith's Λ for GGX, Λ(θ) = (−1 + √(1 + α² tan²θ)) / 2.
inline double lambda(double cos_t, double alpha) {
  const double tan2 = (1 - cos_t * cos_t) / (cos_t * cos_t);
  return 0.5 * (-1 + std::sqrt(1 + alpha * alpha * tan2));
}
// Heitz 2014, eq. 99: the height-correlated masking-shadowing G₂ = 1 / (1 + Λ(v) + Λ(l)).
inline double g2(double nov, double nol, double alpha) {
  return 1 / (1 + lambda(nov, alpha) + lambda(nol, alpha));
}
// Cook–Torrance without Fresnel, times the cosine: f·(n·l) = D G₂ / (4 (n·v)).
inline double lobe_cos(const brdf::Vec3& v, const brdf::Vec3& l, double alpha) {
  if (l.z <= 0 || v.z <= 0) return 0;
  const brdf::Vec3 h = brdf::normalize(brdf::Vec3{v.x + l.x, v.y + l.y, v.z + l.z});
  return ndf(h.z, alpha) * g2(v.z, l.z, alpha) / (4 * v.z);
}

// An LTC given by its world-space inverse matrix (row-major), evaluated as a shader does
// (Heitz et al. 2016, eq. 3): D(ω) = D_o(M⁻¹ω/‖M⁻¹ω‖) |M⁻¹| / ‖M⁻¹ω‖³ with the clamped cosine
// D_o = max(0, z)/π. The value does not change when M⁻¹ is scaled, so a texture may normalize it.
inline double ltc_from_inverse(const std::array<double, 9>& minv, const brdf::Vec3& w) {
  const double ox = minv[0] * w.x + minv[1] * w.y + minv[2] * w.z;
  const double oy = minv[3] * w.x + minv[4] * w.y + minv[5] * w.z;
  const double oz = minv[6] * w.x + minv[7] * w.y + minv[8] * w.z;
  const double det = minv[0] * (minv[4] * minv[8] - minv[5] * minv[7]) -
                     minv[1] * (minv[3] * minv[8] - minv[5] * minv[6]) +
                     minv[2] * (minv[3] * minv[7] - minv[4] * minv[6]);
  const double len2 = ox * ox + oy * oy + oz * oz;
  return std::max(0.0, oz) * std::abs(det) / (kPi * len2 * len2);
}

}  // namespace fl::test::ggx_ref
