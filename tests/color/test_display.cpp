// The display transform of render pictures: OpenColorIO's built-in ACES 1.0 SDR video view to sRGB.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "color/ocio.h"
#include "util/errors.h"

namespace fl::color {
namespace {

// ACES 1.0 reference (aces-dev, RRT + ODT.Academy.RGBmonitor_100nits_dim), by hand for a neutral:
// the RRT's tone scale (segmented spline C5) maps 0.18 to 4.8 and the 48-nit ODT spline (C9) keeps
// 4.8 (its mid point), glow, red modifier and saturation leave a neutral unchanged; the ODT's
// relative luminance is (4.8 − 0.02) / (48 − 0.02) = 0.099625, the dark-to-dim surround
// correction raises it to the power 0.9811 (0.104063), and the sRGB inverse EOTF gives
// 1.055 · 0.104063^(1/2.4) − 0.055 = 0.35598. (A pure 2.4 gamma, the Rec.709 BT.1886 ODT, would
// give 0.104063^(1/2.4) = 0.3896.)
constexpr double kAcesMidGreySrgb = 0.35598;

std::vector<float> through(const DisplayTransform& t, float r, float g, float b) {
  std::vector<float> v{r, g, b};
  t.apply(v);
  return v;
}

TEST(DisplayTransform, AcesSdrVideoMidGreyMatchesTheReference) {
  const DisplayTransform t(SpaceLibrary::builtin(), "acescg", {});
  const auto v = through(t, 0.18f, 0.18f, 0.18f);
  for (float c : v) EXPECT_NEAR(c, kAcesMidGreySrgb, 2e-3);
  EXPECT_EQ(t.description(),
            "display sRGB, view ACES 1.0 - SDR Video (OpenColorIO built-in), exposure +0 EV");
}

TEST(DisplayTransform, HighlightsRollOffInsteadOfClipping) {
  const DisplayTransform t(SpaceLibrary::builtin(), "acescg", {});
  // 4.0 (two stops over a white card) stays below the display's top code, ordered above 1.0.
  const auto four = through(t, 4.0f, 4.0f, 4.0f), one = through(t, 1.0f, 1.0f, 1.0f);
  EXPECT_LT(std::lround(255 * four[1]), 255);
  EXPECT_GT(four[1], one[1]);
  // A saturated gold-like highlight keeps its hue: red above green above blue, none at 255.
  const auto gold = through(t, 4.0f, 2.6f, 0.8f);
  EXPECT_GT(gold[0], gold[1]);
  EXPECT_GT(gold[1], gold[2]);
  EXPECT_LT(std::lround(255 * gold[0]), 255);
}

TEST(DisplayTransform, ExposureIsAScaleBeforeTheView) {
  const DisplayTransform plus(SpaceLibrary::builtin(), "acescg", {"", "", 1.0});
  const DisplayTransform zero(SpaceLibrary::builtin(), "acescg", {});
  const auto a = through(plus, 0.09f, 0.09f, 0.09f), b = through(zero, 0.18f, 0.18f, 0.18f);
  EXPECT_NEAR(a[0], b[0], 1e-5);
}

TEST(DisplayTransform, UntonemappedViewIsTheClippedSrgbEncoding) {
  const DisplayTransform t(SpaceLibrary::builtin(), "lin_rec709", {"sRGB", "Un-tone-mapped", 0});
  const auto v = through(t, 0.18f, 4.0f, -1.0f);
  // IEC 61966-2-1: 1.055 · 0.18^(1/2.4) − 0.055 = 0.46135; 4.0 clips to 1, −1 to 0.
  EXPECT_NEAR(v[0], 0.46135, 1e-4);
  EXPECT_FLOAT_EQ(v[1], 1.0f);
  EXPECT_FLOAT_EQ(v[2], 0.0f);
}

TEST(DisplayTransform, UnknownViewIsAnInputError) {
  EXPECT_THROW(DisplayTransform(SpaceLibrary::builtin(), "acescg", {"sRGB", "Filmic", 0}),
               InputError);
  EXPECT_THROW(DisplayTransform(SpaceLibrary::builtin(), "acescg", {"P3", "", 0}), InputError);
  EXPECT_THROW(DisplayTransform(SpaceLibrary::builtin(), "acescg", {"", "", 40}), InputError);
}

}  // namespace
}  // namespace fl::color

namespace fl::color {
namespace {

// With a config and no --display or --view, pictures use the config's default display and its
// default view (the test config's sRGB has one view, Raw: ACES2065-1 unchanged); the reflectance
// view keeps the built-in Un-tone-mapped unless one is named.
TEST(DisplayTransform, ConfigDefaultViewIsHonoured) {
  const auto lib =
      SpaceLibrary::from_config(std::string(FL_TESTS_DIR) + "/good_input/ocio/studio.ocio");
  const DisplayTransform pictures(lib, "ACES2065-1", {});
  EXPECT_EQ(pictures.display_and_view(), "display sRGB, view Raw");
  const auto v = through(pictures, 0.25f, 0.5f, 0.75f);
  EXPECT_NEAR(v[0], 0.25f, 1e-6);
  EXPECT_NEAR(v[2], 0.75f, 1e-6);
  ViewSettings reflectance;
  reflectance.builtin_view = kUntonemappedView;
  reflectance.builtin_unless_named = true;
  EXPECT_EQ(DisplayTransform(lib, "ACES2065-1", reflectance).display_and_view(),
            "display sRGB, view Un-tone-mapped");
}

}  // namespace
}  // namespace fl::color
