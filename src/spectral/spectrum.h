#pragma once
// Spectra on a uniform wavelength grid, and linear interpolation of tabulated data onto it.
#include <complex>
#include <vector>

namespace fl::spectral {

struct SpectralGrid {
  double start_nm = 360.0;
  double step_nm = 5.0;
  int count = 95;  // 360..830 nm inclusive at 5 nm

  double lambda_nm(int i) const { return start_nm + step_nm * i; }
  double end_nm() const { return lambda_nm(count - 1); }
  // 360..830 nm with the given step (5 or 1 nm in practice).
  static SpectralGrid visible(double step_nm);
  bool operator==(const SpectralGrid&) const = default;
};

struct Spectrum {
  SpectralGrid grid;
  std::vector<double> values;
};

// n + i·kappa per grid wavelength.
struct ComplexIorSpectrum {
  SpectralGrid grid;
  std::vector<std::complex<double>> ior;
};

// Piecewise-linear interpolation of (x, y) samples (x strictly increasing) at xq; outside the
// samples the nearest end value is returned.
double interpolate_linear(const std::vector<double>& x, const std::vector<double>& y, double xq);

// Resamples tabulated (lambda_nm, value) onto a grid with interpolate_linear.
Spectrum resample(const std::vector<double>& lambda_nm, const std::vector<double>& values,
                  const SpectralGrid& grid);

}  // namespace fl::spectral
