#include "fresnel/ground_truth.h"

#include <algorithm>

#include "fresnel/exact.h"
#include "spectral/spectrum.h"
#include "util/codegen.h"

namespace fl::fresnel {

namespace {

// Wavelengths per column pass: a few kilobytes on the stack; the 1 nm grid takes four passes.
constexpr size_t kColumn = 128;

// R(λ) at cosθ for n relative indices, eta_kappa interleaved (η₀, κ₀, η₁, κ₁, ...), each divided
// by eta_outside: a column loop (FL_FLATTEN), each lane rounding as the scalar kernel does.
FL_FLATTEN void reflectance_column(double cos_theta, const double* eta_kappa, double eta_outside,
                                   size_t n, double* __restrict out) {
  for (size_t i = 0; i < n; ++i)
    out[i] = fresnel_conductor<double>(cos_theta, eta_kappa[2 * i] / eta_outside,
                                       eta_kappa[2 * i + 1] / eta_outside);
}

}  // namespace

color::Rgb spectral_reflectance_rgb(const std::vector<color::Rgb>& w,
                                    const spectral::ComplexIorSpectrum& ior, double cos_theta,
                                    double eta_outside) {
  // std::complex<double> is laid out as two doubles (real, imaginary).
  const double* eta_kappa = reinterpret_cast<const double*>(ior.ior.data());
  double r[kColumn];
  color::Rgb out;
  // The sum runs in wavelength order, one term at a time, as R(λ)·w(λ).
  for (size_t start = 0; start < w.size(); start += kColumn) {
    const size_t n = std::min(kColumn, w.size() - start);
    reflectance_column(cos_theta, eta_kappa + 2 * start, eta_outside, n, r);
    for (size_t i = 0; i < n; ++i) out = out + r[i] * w[start + i];
  }
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
