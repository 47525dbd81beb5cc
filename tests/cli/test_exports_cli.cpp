// The exports people have, read to the same presets as the database page they came from: copper
// (Johnson & Christy 1972, main/Cu/nk/Johnson) written as a semicolon table with decimal commas for
// n and k, a table with a trailing separator, a Windows-1252 µm header, and SOPRA .nk with decimal
// commas. The rows are the page's own (the SOPRA file resampled every 5 nm by linear
// interpolation, as the reader samples the page), so each file's F0 must equal the page's.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "spectral/ri_database.h"
#include "test_util.h"

namespace fl {
namespace {

// F0 of the same data read from another file. The SOPRA file is resampled on the reader's own 5 nm
// grid, so every file gives the page's F0 to the presets' six decimals (measured: 0.810767,
// 0.643424, 0.542162 for each); 2e-3 is the acceptance of the exports.
constexpr double kSameF0 = 2e-3;

std::string decimal_comma(double v) {
  std::string s = fmt::format("{}", v);
  std::replace(s.begin(), s.end(), '.', ',');
  return s;
}

// F0 (R, G, B) of `material` from `presets --format csv`.
std::array<double, 3> f0_of(const std::string& material) {
  const auto r = test::run_command(test::cli() + " -q presets '" + material + "' --format csv");
  EXPECT_EQ(r.status, 0) << material << ": " << r.err;
  std::istringstream in(r.out);
  std::string header, row, cell;
  std::getline(in, header);
  std::getline(in, row);
  std::vector<std::string> names, values;
  for (std::istringstream h(header); std::getline(h, cell, ',');) names.push_back(cell);
  for (std::istringstream v(row); std::getline(v, cell, ',');) values.push_back(cell);
  std::array<double, 3> f0{};
  for (int c = 0; c < 3; ++c) {
    const auto it = std::find(names.begin(), names.end(), std::string("f0_") + "rgb"[c]);
    if (it == names.end() || size_t(it - names.begin()) >= values.size()) return {};
    f0[c] = std::stod(values[size_t(it - names.begin())]);
  }
  return f0;
}

// Linear interpolation of the page's rows at `nm`.
double at(const std::vector<double>& x, const std::vector<double>& y, double nm) {
  const auto hi = std::upper_bound(x.begin(), x.end(), nm);
  if (hi == x.begin()) return y.front();
  if (hi == x.end()) return y.back();
  const size_t i = size_t(hi - x.begin());
  const double t = (nm - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

TEST(ExportsCli, EachReaderGivesJohnsonCopperF0) {
  const auto page = spectral::read_refractiveindex_file(std::string(FL_DEFAULT_DB) +
                                                        "/data/main/Cu/nk/Johnson.yml");
  ASSERT_EQ(page.blocks.size(), 1u);
  const auto& b = page.blocks[0];
  ASSERT_GT(b.lambda_nm.size(), 40u);
  std::string semicolon = "wavelength_nm;n;k\n", trailing = "wl,n,k,\n",
              cp1252 = "Wavelength (\xB5m)\tn\tk\n";
  for (size_t i = 0; i < b.lambda_nm.size(); ++i) {
    semicolon +=
        fmt::format("{:.1f};{};{}\n", b.lambda_nm[i], decimal_comma(b.n[i]), decimal_comma(b.k[i]));
    trailing += fmt::format("{:.4f},{},{},\n", b.lambda_nm[i] / 1000, b.n[i], b.k[i]);
    cp1252 += fmt::format("{:.4f}\t{}\t{}\n", b.lambda_nm[i] / 1000, b.n[i], b.k[i]);
  }
  std::string sopra = "4 360 830 94\n";
  for (int i = 0; i <= 94; ++i) {
    const double nm = 360.0 + 5.0 * i;
    sopra += fmt::format("{} {}\n", decimal_comma(std::round(at(b.lambda_nm, b.n, nm) * 1e6) / 1e6),
                         decimal_comma(std::round(at(b.lambda_nm, b.k, nm) * 1e6) / 1e6));
  }
  test::TempDir tmp;
  const auto johnson = f0_of("main/Cu/nk/Johnson");
  ASSERT_GT(johnson[0], 0.5);  // copper: red F0 above 0.5
  for (const auto& [name, text] :
       {std::pair{"cu_semicolon.csv", semicolon}, std::pair{"cu_trailing.csv", trailing},
        std::pair{"cu_cp1252.txt", cp1252}, std::pair{"cu.nk", sopra}}) {
    const auto f0 = f0_of(tmp.file(name, text));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f0[c], johnson[c], kSameF0) << name << " channel " << c;
  }
}

}  // namespace
}  // namespace fl
