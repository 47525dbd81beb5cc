#include "spectral/spectrum.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fl::spectral {

SpectralGrid SpectralGrid::visible(double step_nm) {
  if (!(step_nm > 0.0)) throw std::invalid_argument("wavelength step must be positive");
  SpectralGrid g;
  g.start_nm = 360.0;
  g.step_nm = step_nm;
  g.count = static_cast<int>(std::lround((830.0 - 360.0) / step_nm)) + 1;
  return g;
}

double interpolate_linear(const std::vector<double>& x, const std::vector<double>& y, double xq) {
  if (x.empty()) throw std::invalid_argument("interpolate_linear: no samples");
  if (xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), xq);
  const size_t i = static_cast<size_t>(it - x.begin());
  const double t = (xq - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

Spectrum resample(const std::vector<double>& lambda_nm, const std::vector<double>& values,
                  const SpectralGrid& grid) {
  Spectrum s{grid, std::vector<double>(grid.count)};
  for (int i = 0; i < grid.count; ++i)
    s.values[i] = interpolate_linear(lambda_nm, values, grid.lambda_nm(i));
  return s;
}

}  // namespace fl::spectral
