// CIE colorimetric data (spectral/cie.h): observer and illuminants read from colord-data.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "spectral/cie.h"
#include "spectral/errors.h"

namespace fl::spectral {
namespace {

constexpr double kWhiteTolerance = 1e-4;

TEST(Cie, IlluminantWhitePoints) {
  const auto grid = SpectralGrid::visible(5.0);
  const auto obs = cie1931_2deg(grid, default_colord_dir());
  auto xy = [&](const std::string& name) {
    const auto s = illuminant_spd(name, grid, default_colord_dir());
    double X = 0, Y = 0, Z = 0;
    for (int i = 0; i < grid.count; ++i) {
      X += s.values[i] * obs.x_bar.values[i];
      Y += s.values[i] * obs.y_bar.values[i];
      Z += s.values[i] * obs.z_bar.values[i];
    }
    return std::pair{X / (X + Y + Z), Y / (X + Y + Z)};
  };
  // CIE 15:2004 Table T.3 (2° observer) white points; D60 is the ACES white.
  const auto d65 = xy("D65");
  EXPECT_NEAR(d65.first, 0.31272, kWhiteTolerance);
  EXPECT_NEAR(d65.second, 0.32903, kWhiteTolerance);
  const auto d50 = xy("D50");
  EXPECT_NEAR(d50.first, 0.34567, kWhiteTolerance);
  EXPECT_NEAR(d50.second, 0.35851, kWhiteTolerance);
  const auto a = xy("A");
  EXPECT_NEAR(a.first, 0.44757, kWhiteTolerance);
  EXPECT_NEAR(a.second, 0.40745, kWhiteTolerance);
  const auto d60 = xy("D60");
  EXPECT_NEAR(d60.first, 0.32168, kWhiteTolerance);
  EXPECT_NEAR(d60.second, 0.33767, kWhiteTolerance);
  EXPECT_THROW(illuminant_spd("F99", grid, default_colord_dir()), InputError);
  EXPECT_THROW(illuminant_spd("D1000", grid, default_colord_dir()), InputError);
}

}  // namespace
}  // namespace fl::spectral
