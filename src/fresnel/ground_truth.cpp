#include "fresnel/ground_truth.h"

#include <algorithm>

#include "fresnel/exact.h"
#include "spectral/spectrum.h"
#include "util/codegen.h"

namespace fl::fresnel {

namespace {

// Wavelengths per column pass: a few kilobytes on the stack; the 1 nm grid takes four passes.
constexpr size_t kColumn = 128;

// R(λ) at cosθ for n relative indices, interleaved (η₀, κ₀, η₁, κ₁, ...): a column loop
// (FL_FLATTEN), each lane rounding as the scalar kernel does.
FL_FLATTEN void reflectance_column(double cos_theta, const double* eta_kappa, size_t n,
                                   double* __restrict out) {
  for (size_t i = 0; i < n; ++i)
    out[i] = fresnel_conductor<double>(cos_theta, eta_kappa[2 * i], eta_kappa[2 * i + 1]);
}

}  // namespace

void spectral_reflectance_rgb(const std::vector<color::Rgb>& w,
                              const spectral::ComplexIorSpectrum& ior,
                              std::span<const double> cos_theta, double eta_outside,
                              color::Rgb* out) {
  // std::complex<double> is laid out as two doubles (real, imaginary).
  const double* eta_kappa = reinterpret_cast<const double*>(ior.ior.data());
  // The index relative to the outside medium, divided once for every angle (in vacuum or air,
  // eta_outside = 1, it is the index itself).
  std::vector<double> relative;
  if (eta_outside != 1.0) {
    relative.assign(eta_kappa, eta_kappa + 2 * w.size());
    for (double& x : relative) x /= eta_outside;
    eta_kappa = relative.data();
  }
  double r[kColumn];
  for (size_t a = 0; a < cos_theta.size(); ++a) {
    color::Rgb sum;
    // The sum runs in wavelength order, one term at a time, as R(λ)·w(λ).
    for (size_t start = 0; start < w.size(); start += kColumn) {
      const size_t n = std::min(kColumn, w.size() - start);
      reflectance_column(cos_theta[a], eta_kappa + 2 * start, n, r);
      for (size_t i = 0; i < n; ++i) sum = sum + r[i] * w[start + i];
    }
    out[a] = sum;
  }
}

color::Rgb spectral_reflectance_rgb(const std::vector<color::Rgb>& w,
                                    const spectral::ComplexIorSpectrum& ior, double cos_theta,
                                    double eta_outside) {
  color::Rgb out;
  spectral_reflectance_rgb(w, ior, std::span(&cos_theta, 1), eta_outside, &out);
  return out;
}

color::Rgb process_as_reflectance(const std::vector<color::Rgb>& w,
                                  const spectral::ComplexIorSpectrum& ior, bool kappa) {
  color::Rgb out;
  for (size_t i = 0; i < w.size(); ++i)
    out = out + (kappa ? ior.ior[i].imag() : ior.ior[i].real()) * w[i];
  return out;
}

PointSampled point_sample(const spectral::ComplexIorSpectrum& ior,
                          const std::array<double, 3>& lambda_nm) {
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
