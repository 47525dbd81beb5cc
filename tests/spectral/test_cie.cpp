// The embedded CIE colorimetric data (spectral/cie.h) against published values: the 1931
// observer's tabulated values and area, the equal-energy white, the CIE 15:2004 white points of the
// illuminants built from the daylight components and Planck's law, and CIE's tabulated D65 and A.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "spectral/cie.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

// CIE 15:2004 Table T.3 (2° observer) prints white points to 5 decimals.
constexpr double kCie15WhiteTolerance = 1e-4;
// The ACES white (ACES TB-2014-004) is the daylight locus (CIE 15:2004 eq. 3.3) at
// 6000·1.4388/1.4380 K; the spectrum built from the CIE daylight components there sits 6e-5 to
// 7e-5 from it, as CIE's own D65 table sits 1e-4 below its locus point in y.
constexpr double kDaylightLocusTolerance = 1e-4;
// pbrt-v4 (Pharr, Jakob & Humphreys 2023, §4.6.1): CIE_Y_integral = 106.856895, ∫ ȳ over 360-830
// nm from the 1-nm CIE table (summed in single precision: 2.2e-5 from the double sum).
constexpr double kYIntegral = 106.856895;
constexpr double kYIntegralTolerance = 1e-4;
// The CIE 1931 functions are scaled to equal areas, so E = (1/3, 1/3) to the table's rounding.
constexpr double kEqualEnergyTolerance = 6e-5;

std::pair<double, double> white_xy(const std::string& name, const SpectralGrid& grid) {
  const auto obs = cie1931_2deg(grid);
  const auto s = illuminant_spd(name, grid);
  double X = 0, Y = 0, Z = 0;
  for (int i = 0; i < grid.count; ++i) {
    X += s.values[i] * obs.x_bar.values[i];
    Y += s.values[i] * obs.y_bar.values[i];
    Z += s.values[i] * obs.z_bar.values[i];
  }
  return {X / (X + Y + Z), Y / (X + Y + Z)};
}

double at(const Spectrum& s, double nm) {
  return s.values[static_cast<int>(std::lround((nm - s.grid.start_nm) / s.grid.step_nm))];
}

TEST(Cie, ObserverValuesAndArea) {
  const auto grid1 = SpectralGrid::visible(1.0);
  const auto obs = cie1931_2deg(grid1);
  // CIE 15:2004 Table T.4: the maxima of x̄, ȳ, z̄ and values across the range.
  EXPECT_EQ(at(obs.y_bar, 555), 1.0);
  EXPECT_EQ(*std::max_element(obs.y_bar.values.begin(), obs.y_bar.values.end()), 1.0);
  EXPECT_DOUBLE_EQ(at(obs.x_bar, 600), 1.0622);
  EXPECT_DOUBLE_EQ(at(obs.z_bar, 445), 1.7826);
  EXPECT_DOUBLE_EQ(at(obs.x_bar, 360), 0.0001299);
  EXPECT_DOUBLE_EQ(at(obs.y_bar, 500), 0.323);
  EXPECT_DOUBLE_EQ(at(obs.x_bar, 700), 0.01135916);
  double y = 0;
  for (double v : obs.y_bar.values) y += v;  // × 1 nm
  EXPECT_NEAR(y, kYIntegral, kYIntegralTolerance);
  const auto e = white_xy("E", grid1);
  EXPECT_NEAR(e.first, 1.0 / 3.0, kEqualEnergyTolerance);
  EXPECT_NEAR(e.second, 1.0 / 3.0, kEqualEnergyTolerance);
  // On the 5 nm grid the values are the CIE's 5 nm table (every fifth row of the 1 nm one).
  const auto obs5 = cie1931_2deg(SpectralGrid::visible(5.0));
  EXPECT_EQ(at(obs5.x_bar, 600), 1.0622);
  EXPECT_EQ(at(obs5.z_bar, 445), 1.7826);
}

TEST(Cie, IlluminantWhitePoints) {
  for (double step : {1.0, 5.0}) {
    const auto grid = SpectralGrid::visible(step);
    // CIE 15:2004 Table T.3 (2° observer).
    const auto d65 = white_xy("D65", grid);
    EXPECT_NEAR(d65.first, 0.31271, kCie15WhiteTolerance) << step;
    EXPECT_NEAR(d65.second, 0.32902, kCie15WhiteTolerance) << step;
    const auto d50 = white_xy("D50", grid);
    EXPECT_NEAR(d50.first, 0.34567, kCie15WhiteTolerance) << step;
    EXPECT_NEAR(d50.second, 0.35851, kCie15WhiteTolerance) << step;
    const auto a = white_xy("A", grid);
    EXPECT_NEAR(a.first, 0.44757, kCie15WhiteTolerance) << step;
    EXPECT_NEAR(a.second, 0.40745, kCie15WhiteTolerance) << step;
    const auto d60 = white_xy("D60", grid);
    EXPECT_NEAR(d60.first, 0.32168, kDaylightLocusTolerance) << step;
    EXPECT_NEAR(d60.second, 0.33767, kDaylightLocusTolerance) << step;
  }
  const auto grid = SpectralGrid::visible(5.0);
  EXPECT_THROW(illuminant_spd("F99", grid), InputError);
  EXPECT_THROW(illuminant_spd("D1000", grid), InputError);
}

// CIE 15:2004 Table T.1 (D65, 5 nm, normalised to 100 at 560 nm) is printed to 4 decimals from
// the same recipe (M1, M2 rounded to 3 decimals); Table T.1's A to 3 significant decimals.
constexpr double kTabulatedTolerance = 1e-3;

TEST(Cie, ComputedIlluminantsMatchTheCieTables) {
  const auto grid = SpectralGrid::visible(5.0);
  const auto d65 = illuminant_spd("D65", grid);
  EXPECT_NEAR(at(d65, 560), 100.0, kTabulatedTolerance);
  EXPECT_NEAR(at(d65, 400), 82.7549, kTabulatedTolerance);
  EXPECT_NEAR(at(d65, 500), 109.354, kTabulatedTolerance);
  EXPECT_NEAR(at(d65, 600), 90.0062, kTabulatedTolerance);
  EXPECT_NEAR(at(d65, 700), 71.6091, kTabulatedTolerance);
  EXPECT_NEAR(at(d65, 365), 49.3637, kTabulatedTolerance);  // between the 10 nm components
  const auto a = illuminant_spd("A", grid);
  EXPECT_NEAR(at(a, 560), 100.0, 1e-12);
  EXPECT_NEAR(at(a, 400), 14.708, kTabulatedTolerance);
  EXPECT_NEAR(at(a, 600), 129.043, kTabulatedTolerance);
  EXPECT_NEAR(at(a, 780), 241.675, kTabulatedTolerance);
}

}  // namespace
}  // namespace fl::spectral
