// The run's colour pipeline (analysis/pipeline/context.h): reflectance spectrum → working-space
// RGB, against published white points and matrices, and the default illuminant of each space.
// Without adaptation, the perfect reflector lands on the illuminant's own white expressed in the
// space; with adaptation it lands on the space's white (von Kries maps white to white), so only the
// unadapted pipeline is checked against data here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/pipeline/context.h"
#include "color/rgb_space.h"

namespace fl::analysis {
namespace {

using color::Mat3;
using color::Rgb;

// CIE 15:2004 Table T.3 chromaticities are printed to 5 decimals; the embedded observer and the
// computed D65 summed over 360-830 nm at 5 nm reproduce them within 1e-4 (tests/spectral/test_cie).
constexpr double kWhiteRgbTolerance = 2e-4;
// The ACES white is the daylight locus at 6000·1.4388/1.4380 K; the daylight spectrum built there
// from the CIE basis sits 7e-5 from it in xy (tests/spectral/test_cie.cpp), 5.6e-4 in ACEScg.
constexpr double kD60WhiteRgbTolerance = 1e-3;

double xyz_component(const color::Xyz& v, int i) {
  return i == 0 ? v.X : i == 1 ? v.Y : v.Z;
}

Rgb perfect_reflector(const std::string& space, const std::string& illuminant) {
  Settings s;
  s.space = space;
  s.illuminant = illuminant;
  s.adaptation = "none";
  const Context ctx(s);
  return ctx.spectrum_to_rgb(std::vector<double>(ctx.grid().count, 1.0));
}

TEST(Pipeline, PerfectReflectorUnderD65InRec709IsTheCieD65White) {
  // BT.709 RGB → XYZ as published (10 decimals; see tests/color/test_color.cpp), inverted here.
  const Mat3 rec709{{0.4123907993, 0.3575843394, 0.1804807884, 0.2126390059, 0.7151686788,
                     0.0721923154, 0.0193308187, 0.1191947798, 0.9505321522}};
  const color::Xyz d65 = color::xyz_from_xy({0.31272, 0.32903});  // CIE 15:2004 Table T.3
  const Rgb want = rec709.inverse() * d65;
  const Rgb got = perfect_reflector("lin_rec709", "D65");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], kWhiteRgbTolerance) << c;
  // And it is not the space's white exactly: the tabulated D65 is 2e-5 off (0.3127, 0.3290).
  EXPECT_GT(std::abs(got.b - 1.0), 1e-5);
}

TEST(Pipeline, PerfectReflectorUnderD60InAcescgIsTheAcesWhite) {
  const Rgb got = perfect_reflector("acescg", "D60");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], 1.0, kD60WhiteRgbTolerance) << c;
}

TEST(Pipeline, PerfectReflectorUnderIlluminantAInAcescg) {
  // CIE 15:2004 Table T.3: A at (0.44757, 0.40745); ACEScg RGB → XYZ as published (S-2014-004).
  const Mat3 ap1{{0.6624541811, 0.1340042065, 0.1561876870, 0.2722287168, 0.6740817658,
                  0.0536895174, -0.0055746495, 0.0040607335, 1.0103391003}};
  const Rgb want = ap1.inverse() * color::xyz_from_xy({0.44757, 0.40745});
  const Rgb got = perfect_reflector("acescg", "A");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], kWhiteRgbTolerance) << c;
}

// The illuminant follows the working space: the default one is the spectrum whose white is the
// space's white (CIE 15:2004 D65 x = 0.31272, y = 0.32903 for the Rec.709/Rec.2020/P3-D65 white
// 0.3127, 0.3290; the D60 daylight for the ACES white 0.32168, 0.33767), so the unadapted perfect
// reflector lands on RGB (1, 1, 1) within the published rounding of the two whites.
TEST(Pipeline, DefaultIlluminantIsTheSpacesReferenceWhite) {
  for (const auto& [space, illuminant] :
       std::vector<std::pair<std::string, std::string>>{{"acescg", "D60"},
                                                        {"aces2065-1", "D60"},
                                                        {"lin_rec709", "D65"},
                                                        {"lin_rec2020", "D65"},
                                                        {"lin_p3d65", "D65"}}) {
    Settings s;
    s.space = space;
    s.adaptation = "none";
    const Context ctx(s);
    EXPECT_EQ(ctx.settings().illuminant, illuminant) << space;
    const Rgb w = ctx.spectrum_to_rgb(std::vector<double>(ctx.grid().count, 1.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], 1.0, kD60WhiteRgbTolerance) << space << " " << c;
  }
  Settings s;
  s.space = "lin_rec709";
  s.illuminant = "D50";
  EXPECT_EQ(Context(s).settings().illuminant, "D50");  // --illuminant overrides
}

const std::string kStudioConfig = std::string(FL_TESTS_DIR) + "/good_input/ocio/studio.ocio";

// A config's matrices to CIE XYZ D65 carry each space's white adapted to D65. A space whose matrix
// is one of the built-in spaces' (ACEScg through OCIO's built-in AP1 transform, Rec.2020 from its
// published primaries) gets that space's primaries, white and illuminant, so it gives the same
// colours and the same CIELAB as the built-in space.
TEST(Pipeline, OcioSpacesTakeTheirWhiteFromTheConfig) {
  for (const auto& [config_space, builtin] : std::vector<std::pair<std::string, std::string>>{
           {"ACEScg", "acescg"}, {"Linear Rec.2020", "lin_rec2020"}}) {
    Settings a, b;
    a.ocio_config = kStudioConfig;
    a.space = config_space;
    b.space = builtin;
    const Context ca(a), cb(b);
    EXPECT_EQ(ca.settings().illuminant, cb.settings().illuminant) << config_space;
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(xyz_component(ca.space().white, i), xyz_component(cb.space().white, i), 1e-12);
    for (size_t k = 0; k < ca.rgb_weights().size(); ++k)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(ca.rgb_weights()[k][c], cb.rgb_weights()[k][c], 1e-12) << config_space;
  }
}

// A space the built-ins do not know keeps D65, the white of the config's XYZ space; --ocio-white
// names another, and the matrix is adapted back to it (white RGB (1, 1, 1) maps to that white).
TEST(Pipeline, OcioSpaceWithoutAKnownMatrixIsD65UnlessTold) {
  Settings s;
  s.ocio_config = kStudioConfig;
  s.space = "Linear Adobe RGB (1998)";
  const Context d65(s);
  EXPECT_EQ(d65.settings().illuminant, "D65");
  const color::Chromaticity w = color::xy_from_xyz(d65.space().white);
  EXPECT_NEAR(w.x, 0.3127, 1e-6);
  EXPECT_NEAR(w.y, 0.3290, 1e-6);
  s.ocio_white = "ACES";
  const Context aces(s);
  EXPECT_EQ(aces.settings().illuminant, "D60");
  const color::Chromaticity wa = color::xy_from_xyz(aces.space().rgb_to_xyz * Rgb{1, 1, 1});
  EXPECT_NEAR(wa.x, 0.32168, 1e-6);
  EXPECT_NEAR(wa.y, 0.33767, 1e-6);
}

}  // namespace
}  // namespace fl::analysis
