#include "spectral/cie.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

#include "spectral/cie_tables.h"
#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

std::vector<double> wavelengths(double start, double step, int count) {
  std::vector<double> out(count);
  for (int i = 0; i < count; ++i) out[i] = start + step * i;
  return out;
}

Spectrum tabulated(const double* values, const SpectralGrid& grid) {
  using namespace cie_tables;
  return resample(wavelengths(kCmfStartNm, kCmfStepNm, kCmfCount),
                  std::vector<double>(values, values + kCmfCount), grid);
}

}  // namespace

Observer cie1931_2deg(const SpectralGrid& grid) {
  return {tabulated(cie_tables::kXBar, grid), tabulated(cie_tables::kYBar, grid),
          tabulated(cie_tables::kZBar, grid)};
}

Spectrum daylight_spd(double cct, const SpectralGrid& grid, bool round_m) {
  if (!(cct >= 4000.0 && cct <= 25000.0))
    throw InputError(fmt::format("daylight CCT {} K is outside 4000-25000 K", cct));
  // CIE 15:2004 eq. 3.3/3.4: chromaticity of daylight from its CCT.
  const double t = cct, t2 = t * t, t3 = t2 * t;
  const double xd = t <= 7000.0 ? 0.244063 + 0.09911e3 / t + 2.9678e6 / t2 - 4.6070e9 / t3
                                : 0.237040 + 0.24748e3 / t + 1.9018e6 / t2 - 2.0064e9 / t3;
  const double yd = -3.000 * xd * xd + 2.870 * xd - 0.275;
  // CIE 15:2004 eq. 3.5: weights of the daylight components.
  const double m = 0.0241 + 0.2562 * xd - 0.7341 * yd;
  double m1 = (-1.3515 - 1.7703 * xd + 5.9114 * yd) / m;
  double m2 = (0.0300 - 31.4424 * xd + 30.0717 * yd) / m;
  if (round_m) {
    m1 = std::round(m1 * 1000.0) / 1000.0;
    m2 = std::round(m2 * 1000.0) / 1000.0;
  }
  using namespace cie_tables;
  std::vector<double> s(kDaylightCount);
  for (int i = 0; i < kDaylightCount; ++i) s[i] = kS0[i] + m1 * kS1[i] + m2 * kS2[i];
  return resample(wavelengths(kDaylightStartNm, kDaylightStepNm, kDaylightCount), s, grid);
}

Spectrum illuminant_a(const SpectralGrid& grid) {
  // CIE 15:2004 eq. 3.1, λ in nm: c2 / (T λ) with c2 = 1.435e7 nm·K and T = 2848 K, the
  // temperature the CIE fixed with that c2 (2856 K on today's scale).
  constexpr double kC2 = 1.435e7, kT = 2848.0;
  const double at560 = std::expm1(kC2 / (kT * 560.0));
  Spectrum s{grid, std::vector<double>(grid.count)};
  for (int i = 0; i < grid.count; ++i) {
    const double nm = grid.lambda_nm(i);
    s.values[i] = 100.0 * std::pow(560.0 / nm, 5.0) * at560 / std::expm1(kC2 / (kT * nm));
  }
  return s;
}

Spectrum illuminant_spd(const std::string& name_in, const SpectralGrid& grid) {
  std::string name = name_in;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return std::toupper(c); });
  // c2 = 1.4388e-2 m·K today; the D-series were defined with 1.4380e-2, hence the rescaling.
  constexpr double kC2Ratio = 1.4388 / 1.4380;
  if (name == "D50") return daylight_spd(5000.0 * kC2Ratio, grid, true);
  if (name == "D55") return daylight_spd(5500.0 * kC2Ratio, grid, true);
  if (name == "D65") return daylight_spd(6500.0 * kC2Ratio, grid, true);
  if (name == "D75") return daylight_spd(7500.0 * kC2Ratio, grid, true);
  if (name == "A") return illuminant_a(grid);
  if (name == "E") return Spectrum{grid, std::vector<double>(grid.count, 1.0)};
  if (name == "D60") return daylight_spd(6000.0 * kC2Ratio, grid);
  if (name.size() >= 2 && name[0] == 'D') {
    double cct;
    if (parse_finite(std::string_view(name).substr(1), cct) && cct >= 4000 && cct <= 25000)
      return daylight_spd(cct, grid);
  }
  throw InputError(
      fmt::format("unknown illuminant '{}' (expected D50, D55, D60, D65, D75, A, E or Dnnnn with "
                  "4000 <= nnnn <= 25000)",
                  name_in));
}

}  // namespace fl::spectral
