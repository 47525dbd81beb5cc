#include "fresnel/derive.h"

#include <algorithm>
#include <cmath>

#include "fresnel/models/gulbrandsen.h"
#include "fresnel/models/schlick.h"

namespace fl::fresnel {

DerivedParameters derive_parameters(const std::vector<color::Rgb>& w, const color::Mat3& rgb_to_xyz,
                                    const spectral::ComplexIorSpectrum& ior_absolute,
                                    double eta_outside, const std::array<double, 3>& ps_nm) {
  spectral::ComplexIorSpectrum ior = ior_absolute;
  for (auto& v : ior.ior) v /= eta_outside;
  DerivedParameters d;
  d.f0 = spectral_reflectance_rgb(w, ior, 1.0, 1.0);
  d.f82 = spectral_reflectance_rgb(w, ior, kCosTheta82, 1.0);
  const auto ps = point_sample(ior, ps_nm);
  d.eta_ps = ps.eta;
  d.kappa_ps = ps.kappa;
  d.eta_refl = process_as_reflectance(w, ior, false);
  d.kappa_refl = process_as_reflectance(w, ior, true);
  for (int c = 0; c < 3; ++c) {
    d.f82_tint[c] = d.f82[c] / schlick(kCosTheta82, d.f0[c]);
    d.g_refl_eta[c] = gulbrandsen_g(d.f0[c], d.eta_refl[c]);
    d.g_ps_eta[c] = gulbrandsen_g(d.f0[c], d.eta_ps[c]);
  }
  d.eta_rep = (rgb_to_xyz * d.eta_refl).Y;
  d.kappa_rep = (rgb_to_xyz * d.kappa_refl).Y;
  return d;
}

}  // namespace fl::fresnel
