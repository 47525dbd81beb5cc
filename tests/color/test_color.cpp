// Colorimetry: adaptation, OCIO matrices, CIELAB, CIEDE2000.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "color/colorimetry.h"
#include "color/lab.h"
#include "color/ocio.h"
#include "color/rgb_space.h"
#include "spectral/errors.h"
#include "test_util.h"

namespace fl::color {
namespace {

TEST(Adaptation, MapsSourceWhiteToDestinationWhite) {
  const Xyz d65 = xyz_from_xy({0.3127, 0.3290}), aces = xyz_from_xy({0.32168, 0.33767});
  for (auto method : {Adaptation::Bradford, Adaptation::Cat02}) {
    const Xyz w = adaptation_matrix(method, d65, aces) * RgbT<double>{d65.X, d65.Y, d65.Z};
    EXPECT_NEAR(w.X, aces.X, 1e-12);
    EXPECT_NEAR(w.Y, aces.Y, 1e-12);
    EXPECT_NEAR(w.Z, aces.Z, 1e-12);
  }
}

// OpenColorIO's built-in AP1 → linear Rec.709 (Bradford) must equal our composition from the
// published primaries: M709⁻¹ · Bradford(ACES white → D65) · M_AP1.
constexpr double kOcioMatrixTolerance = 1e-6;

TEST(Ocio, BuiltinConversionsMatchPrimaries) {
  const auto lib = SpaceLibrary::builtin();
  const auto ap1 = builtin_space("acescg"), rec709 = builtin_space("lin_rec709");
  const Mat3 ours = rec709.xyz_to_rgb * adaptation_matrix(Adaptation::Bradford, ap1.white, rec709.white) * ap1.rgb_to_xyz;
  const Mat3 ocio = lib.conversion("acescg", "lin_rec709");
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(ocio.m[i], ours.m[i], kOcioMatrixTolerance) << i;
  // ACEScg → ACES2065-1 involves no adaptation (same white).
  const auto ap0 = builtin_space("aces2065-1");
  const Mat3 ours0 = ap0.xyz_to_rgb * ap1.rgb_to_xyz;
  const Mat3 ocio0 = lib.conversion("acescg", "aces2065-1");
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(ocio0.m[i], ours0.m[i], kOcioMatrixTolerance) << i;
  // Round trip through every space is the identity; white stays white.
  for (const auto& a : builtin_space_names()) {
    const Mat3 rt = lib.conversion(a, "lin_rec2020") * lib.conversion("lin_rec2020", a);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(rt.m[i], i % 4 == 0 ? 1.0 : 0.0, 1e-12) << a;
    const Rgb w = transform_rgb(lib.conversion("acescg", a), {1, 1, 1});
    EXPECT_NEAR(w.r, 1.0, 1e-6) << a;
    EXPECT_NEAR(w.g, 1.0, 1e-6) << a;
    EXPECT_NEAR(w.b, 1.0, 1e-6) << a;
  }
}

TEST(Ocio, UserConfigSpacesByName) {
  test::TempDir tmp;
  // A minimal studio-style config: linear Rec.709 defined by its matrix to CIE-XYZ-D65.
  const auto config = tmp.file("config.ocio", R"(ocio_profile_version: 2
roles:
  default: CIE-XYZ-D65
  cie_xyz_d65_interchange: CIE-XYZ-D65
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: CIE-XYZ-D65}
colorspaces:
  - !<ColorSpace>
    name: CIE-XYZ-D65
    isdata: false
  - !<ColorSpace>
    name: Linear Rec.709 (sRGB)
    isdata: false
    to_scene_reference: !<MatrixTransform> {matrix: [0.412390799265959, 0.357584339383878, 0.180480788401834, 0, 0.212639005871510, 0.715168678767756, 0.072192315360734, 0, 0.019330818715592, 0.119194779794626, 0.950532152249661, 0, 0, 0, 0, 1]}
)");
  const auto lib = SpaceLibrary::from_config(config);
  const RgbSpace s = lib.space("Linear Rec.709 (sRGB)");
  const RgbSpace ref = builtin_space("lin_rec709");
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(s.rgb_to_xyz.m[i], ref.rgb_to_xyz.m[i], 1e-6);
  EXPECT_THROW(lib.space("nope"), InputError);
}

// Sharma, Wu & Dalal 2005, supplementary test data, to the published 4 decimals.
constexpr double kSharmaTolerance = 1e-4;

TEST(Ciede2000, SharmaWuDalalPairs) {
  std::ifstream in(std::string(FL_SHARED_TESTDATA) + "/ciede2000_sharma2005.csv");
  ASSERT_TRUE(in) << "missing shared test data";
  std::string line;
  int pairs = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("pair", 0) == 0) continue;
    std::stringstream ss(line);
    std::string f;
    std::vector<double> v;
    while (std::getline(ss, f, ',')) v.push_back(std::stod(f));
    ASSERT_EQ(v.size(), 8u);
    const Lab a{v[1], v[2], v[3]}, b{v[4], v[5], v[6]};
    EXPECT_NEAR(ciede2000(a, b), v[7], kSharmaTolerance) << "pair " << v[0];
    EXPECT_NEAR(ciede2000(b, a), v[7], kSharmaTolerance) << "pair " << v[0] << " (swapped)";
    ++pairs;
  }
  EXPECT_EQ(pairs, 34);
}

TEST(Lab, WhiteAndBlack) {
  const Xyz white = xyz_from_xy({0.32168, 0.33767});
  const Lab w = xyz_to_lab(white, white);
  EXPECT_NEAR(w.L, 100.0, 1e-12);
  EXPECT_NEAR(w.a, 0.0, 1e-12);
  const Lab k = xyz_to_lab(Xyz{0, 0, 0}, white);
  EXPECT_NEAR(k.L, 0.0, 1e-12);
  // Y = 0.18 → L* = 116·0.18^(1/3) − 16 = 49.4961.
  EXPECT_NEAR(xyz_to_lab(Xyz{0.18 * white.X, 0.18, 0.18 * white.Z}, white).L, 49.49611, 1e-4);
}

}  // namespace
}  // namespace fl::color
