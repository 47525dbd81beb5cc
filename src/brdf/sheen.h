#pragma once
// The sheen lobe of Filament's cloth model, whose directional albedo is the B channel of Filament's
// DFG table: the "Charlie" NDF with Neubelt & Pettineo's visibility.
#include <cmath>
#include <numbers>

namespace fl::brdf {

// Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF", eq. 2:
// D(h) = (2 + 1/α) sin(θ_h)^(1/α) / (2π); 1/(2π)·(2 + 1/α) normalizes ∫ D(h)(n·h) dω_h to one.
inline double charlie_ndf(double noh, double alpha) {
  const double inv_alpha = 1.0 / alpha;
  const double sin2 = std::fmax(0.0, 1.0 - noh * noh);
  return (2.0 + inv_alpha) * std::pow(sin2, 0.5 * inv_alpha) / (2.0 * std::numbers::pi);
}

// Neubelt & Pettineo 2013, "Crafting a Next-Gen Material Pipeline for The Order: 1886": the sheen
// visibility V = 1 / (4 (n·l + n·v − (n·l)(n·v))), which already holds the 1/(4 (n·l)(n·v)) of the
// microfacet BRDF: f = D V.
inline double neubelt_visibility(double nov, double nol) {
  return 1.0 / (4.0 * (nol + nov - nol * nov));
}

}  // namespace fl::brdf
