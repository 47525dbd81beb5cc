#include "spectral/cie.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "spectral/errors.h"
#include "spectral/text_file.h"

namespace fl::spectral {

namespace {

// One data row of a CGATS file: `columns` finite numbers (any number when the format is not given).
template <class Fields>
std::vector<double> cgats_row(const std::string& path, int line, const Fields& fields,
                              size_t columns) {
  std::vector<double> row;
  for (auto f : fields) {
    double v;
    if (!parse_finite(f, v))
      throw InputError(path, line, fmt::format("'{}' is not a finite number", f));
    row.push_back(v);
  }
  if (columns != 0 && row.size() != columns)
    throw InputError(path, line, fmt::format("expected {} values, found {}", columns, row.size()));
  return row;
}

// The wavelengths of SPECTRAL_BANDS samples over [start, end], once the range and every data set
// are checked against them.
std::vector<double> cgats_wavelengths(const std::string& path, double start, double end,
                                      double bands, const std::vector<std::vector<double>>& sets) {
  if (bands < 2 || bands > 100000 || !(end > start) || bands != std::floor(bands))
    throw InputError(path, 0, "SPECTRAL_BANDS / range are inconsistent");
  if (!(start > 0.0))
    throw InputError(path, 0, fmt::format("SPECTRAL_START_NM {:g} must be positive", start));
  // Every spectrum read here is resampled onto 360-830 nm: a file that misses it is not usable.
  if (end < 360.0 || start > 830.0)
    throw InputError(
        path, 0,
        fmt::format("range {:g}-{:g} nm misses the visible range 360-830 nm entirely", start, end));
  if (sets.empty()) throw InputError(path, 0, "no data");
  const int n = static_cast<int>(bands);
  for (const auto& s : sets)
    if (static_cast<int>(s.size()) != n)
      throw InputError(
          path, 0, fmt::format("SPECTRAL_BANDS is {} but a data set has {} values", n, s.size()));
  std::vector<double> lambda_nm;
  for (int i = 0; i < n; ++i) lambda_nm.push_back(start + (end - start) * i / (n - 1));
  return lambda_nm;
}

}  // namespace

CgatsSpectra read_cgats_spectra(const std::string& path) {
  const std::string text = read_text_file(path);
  const auto lines = split_lines(text);
  double start = 0, end = 0, bands = 0;
  bool have_start = false, have_end = false, have_bands = false, in_format = false, in_data = false;
  CgatsSpectra out;
  size_t columns = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i + 1);
    const auto t = trim(lines[i]);
    if (t.empty() || t[0] == '#') continue;
    auto fields = split_fields(t, " \t");
    const std::string key(fields[0]);
    if (in_format) {
      if (key == "END_DATA_FORMAT") {
        in_format = false;
        continue;
      }
      columns += fields.size();
      continue;
    }
    if (in_data) {
      if (key == "END_DATA") {
        in_data = false;
        continue;
      }
      out.sets.push_back(cgats_row(path, line, fields, columns));
      continue;
    }
    auto number = [&](double& v, bool& have) {
      if (fields.size() < 2 || !parse_finite(fields[1], v))
        throw InputError(path, line, fmt::format("{} needs a number", key));
      have = true;
    };
    if (key == "SPECTRAL_START_NM")
      number(start, have_start);
    else if (key == "SPECTRAL_END_NM")
      number(end, have_end);
    else if (key == "SPECTRAL_BANDS")
      number(bands, have_bands);
    else if (key == "BEGIN_DATA_FORMAT")
      in_format = true;
    else if (key == "BEGIN_DATA")
      in_data = true;
  }
  if (!have_start || !have_end || !have_bands)
    throw InputError(
        path, 0, "not a spectral CGATS file (SPECTRAL_START_NM, SPECTRAL_END_NM, SPECTRAL_BANDS)");
  if (in_data || in_format)
    throw InputError(path, static_cast<int>(lines.size()), "truncated: missing END_DATA");
  out.lambda_nm = cgats_wavelengths(path, start, end, bands, out.sets);
  return out;
}

std::string default_colord_dir() {
  if (const char* env = std::getenv("FRESNEL_LAB_COLORD"); env && *env) return env;
  return FRESNEL_LAB_COLORD_DIR;
}

Observer cie1931_2deg(const SpectralGrid& grid, const std::string& colord_dir) {
  const std::string path = colord_dir + "/cmf/CIE1931-2deg-XYZ.cmf";
  const auto c = read_cgats_spectra(path);
  if (c.sets.size() != 3) throw InputError(path, 0, "expected 3 data sets (x̄, ȳ, z̄)");
  return {resample(c.lambda_nm, c.sets[0], grid), resample(c.lambda_nm, c.sets[1], grid),
          resample(c.lambda_nm, c.sets[2], grid)};
}

Spectrum daylight_spd(double cct, const SpectralGrid& grid, const std::string& colord_dir) {
  if (!(cct >= 4000.0 && cct <= 25000.0))
    throw InputError(fmt::format("daylight CCT {} K is outside 4000-25000 K", cct));
  // CIE 15:2004 eq. 3.3/3.4: chromaticity of daylight from its CCT.
  const double t = cct, t2 = t * t, t3 = t2 * t;
  const double xd = t <= 7000.0 ? 0.244063 + 0.09911e3 / t + 2.9678e6 / t2 - 4.6070e9 / t3
                                : 0.237040 + 0.24748e3 / t + 1.9018e6 / t2 - 2.0064e9 / t3;
  const double yd = -3.000 * xd * xd + 2.870 * xd - 0.275;
  // CIE 15:2004 eq. 3.5: weights of the daylight basis vectors.
  const double m = 0.0241 + 0.2562 * xd - 0.7341 * yd;
  const double m1 = (-1.3515 - 1.7703 * xd + 5.9114 * yd) / m;
  const double m2 = (0.0300 - 31.4424 * xd + 30.0717 * yd) / m;
  const std::string path = colord_dir + "/ref/CIE-1986-daylight-SPD.cmf";
  const auto c = read_cgats_spectra(path);
  if (c.sets.size() != 3) throw InputError(path, 0, "expected 3 data sets (S0, S1, S2)");
  std::vector<double> s(c.lambda_nm.size());
  for (size_t i = 0; i < s.size(); ++i) s[i] = c.sets[0][i] + m1 * c.sets[1][i] + m2 * c.sets[2][i];
  return resample(c.lambda_nm, s, grid);
}

Spectrum illuminant_spd(const std::string& name_in, const SpectralGrid& grid,
                        const std::string& colord_dir) {
  std::string name = name_in;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return std::toupper(c); });
  // c2 = 1.4388e-2 m·K today; the D-series were defined with 1.4380e-2, hence the rescaling.
  constexpr double kC2Ratio = 1.4388 / 1.4380;
  auto tabulated = [&](const char* file) {
    const std::string path = colord_dir + "/illuminant/" + file;
    const auto c = read_cgats_spectra(path);
    return resample(c.lambda_nm, c.sets.at(0), grid);
  };
  if (name == "D65") return tabulated("CIE-D65.sp");
  if (name == "D50") return tabulated("CIE-D50.sp");
  if (name == "D55") return tabulated("CIE-D55.sp");
  if (name == "A") return tabulated("CIE-A.sp");
  if (name == "E") return Spectrum{grid, std::vector<double>(grid.count, 1.0)};
  if (name == "D60") return daylight_spd(6000.0 * kC2Ratio, grid, colord_dir);
  if (name == "D75") return daylight_spd(7500.0 * kC2Ratio, grid, colord_dir);
  if (name.size() >= 2 && name[0] == 'D') {
    double cct;
    if (parse_finite(std::string_view(name).substr(1), cct) && cct >= 4000 && cct <= 25000)
      return daylight_spd(cct, grid, colord_dir);
  }
  throw InputError(
      fmt::format("unknown illuminant '{}' (expected D50, D55, D60, D65, D75, A, E or Dnnnn with "
                  "4000 <= nnnn <= 25000)",
                  name_in));
}

}  // namespace fl::spectral
