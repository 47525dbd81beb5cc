#include "fresnel/ground_truth.h"

#include "fresnel/exact.h"
#include "spectral/spectrum.h"

namespace fl::fresnel {

color::Rgb spectral_reflectance_rgb(const std::vector<color::Rgb>& w, const spectral::ComplexIorSpectrum& ior,
                                    double cos_theta, double eta_outside) {
  color::Rgb out;
  for (size_t i = 0; i < w.size(); ++i) out = out + fresnel_conductor(cos_theta, ior.ior[i] / eta_outside) * w[i];
  return out;
}

color::Rgb process_as_reflectance(const std::vector<color::Rgb>& w, const spectral::ComplexIorSpectrum& ior,
                                  bool kappa) {
  color::Rgb out;
  for (size_t i = 0; i < w.size(); ++i) out = out + (kappa ? ior.ior[i].imag() : ior.ior[i].real()) * w[i];
  return out;
}

PointSampled point_sample(const spectral::ComplexIorSpectrum& ior, const std::array<double, 3>& lambda_nm) {
  std::vector<double> x(ior.grid.count), n(ior.grid.count), k(ior.grid.count);
  for (int i = 0; i < ior.grid.count; ++i) {
    x[i] = ior.grid.lambda_nm(i);
    n[i] = ior.ior[i].real();
    k[i] = ior.ior[i].imag();
  }
  PointSampled p;
  for (int c = 0; c < 3; ++c) {
    p.eta[c] = spectral::interpolate_linear(x, n, lambda_nm[c]);
    p.kappa[c] = spectral::interpolate_linear(x, k, lambda_nm[c]);
  }
  return p;
}

}  // namespace fl::fresnel
