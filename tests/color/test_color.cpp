// Colorimetry: adaptation, OCIO matrices, CIELAB, CIEDE2000.
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <sstream>
#include <vector>

#include "color/colorimetry.h"
#include "color/lab.h"
#include "color/ocio.h"
#include "color/rgb_space.h"
#include "csv_reader.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::color {
namespace {

// Published RGB → XYZ matrices (row-major), each to the digits given:
//   acescg, aces2065-1: ACES S-2014-004 and SMPTE ST 2065-1 (AP1, AP0 with the ACES white), 10
//   decimals; lin_rec709, lin_rec2020, lin_p3d65: ITU-R BT.709, BT.2020 and SMPTE EG 432-1
//   primaries with D65 at (0.3127, 0.3290), as OpenColorIO's built-in config and colour-science
//   print them, 10 decimals.
constexpr double kPublishedMatrixTolerance = 1e-9;

struct PublishedMatrix {
  const char* space;
  std::array<double, 9> rgb_to_xyz;
};
const std::vector<PublishedMatrix> kPublishedMatrices = {
    {"acescg",
     {0.6624541811, 0.1340042065, 0.1561876870, 0.2722287168, 0.6740817658, 0.0536895174,
      -0.0055746495, 0.0040607335, 1.0103391003}},
    {"aces2065-1",
     {0.9525523959, 0.0, 0.0000936786, 0.3439664498, 0.7281660966, -0.0721325464, 0.0, 0.0,
      1.0088251844}},
    {"lin_rec709",
     {0.4123907993, 0.3575843394, 0.1804807884, 0.2126390059, 0.7151686788, 0.0721923154,
      0.0193308187, 0.1191947798, 0.9505321522}},
    {"lin_rec2020",
     {0.6369580483, 0.1446169036, 0.1688809752, 0.2627002120, 0.6779980715, 0.0593017165, 0.0,
      0.0280726930, 1.0609850577}},
    {"lin_p3d65",
     {0.4865709486, 0.2656676932, 0.1982172852, 0.2289745641, 0.6917385218, 0.0792869141, 0.0,
      0.0451133819, 1.0439443689}},
};

TEST(RgbSpace, BuiltinMatricesMatchPublishedValues) {
  ASSERT_EQ(builtin_space_names().size(), kPublishedMatrices.size());
  for (const auto& p : kPublishedMatrices) {
    const RgbSpace s = builtin_space(p.space);
    for (int i = 0; i < 9; ++i)
      EXPECT_NEAR(s.rgb_to_xyz.m[i], p.rgb_to_xyz[i], kPublishedMatrixTolerance)
          << p.space << " " << i;
    const Mat3 id = s.rgb_to_xyz * s.xyz_to_rgb;
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(id.m[i], i % 4 == 0 ? 1.0 : 0.0, 1e-12) << p.space;
  }
  // The ACES white (ACES TB-2014-004) and D65 (ITU-R BT.709), as chromaticities.
  const Chromaticity aces = xy_from_xyz(builtin_space("acescg").white),
                     d65 = xy_from_xyz(builtin_space("lin_rec709").white);
  EXPECT_NEAR(aces.x, 0.32168, 1e-12);
  EXPECT_NEAR(aces.y, 0.33767, 1e-12);
  EXPECT_NEAR(d65.x, 0.3127, 1e-12);
  EXPECT_NEAR(d65.y, 0.3290, 1e-12);
}

// Bruce Lindbloom's sRGB matrix and Bradford D65 → D50 matrix (brucelindbloom.com, "RGB/XYZ
// Matrices" and "Chromatic Adaptation"), computed with the ASTM E308 whites D65 = (0.95047, 1,
// 1.08883) and D50 = (0.96422, 1, 0.82521), printed to 7 decimals.
constexpr double kLindbloomTolerance = 6e-8;

TEST(RgbSpace, PrimariesToMatrixMatchesLindbloomsSrgbMatrix) {
  const Xyz d65{0.95047, 1.0, 1.08883};
  const Mat3 m =
      rgb_to_xyz_from_primaries({0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, xy_from_xyz(d65));
  const std::array<double, 9> lindbloom{0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522,
                                        0.0721750, 0.0193339, 0.1191920, 0.9503041};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(m.m[i], lindbloom[i], kLindbloomTolerance) << i;
}

TEST(Adaptation, BradfordMatchesLindbloomsD65ToD50Matrix) {
  const Mat3 m =
      adaptation_matrix(Adaptation::Bradford, {0.95047, 1.0, 1.08883}, {0.96422, 1.0, 0.82521});
  const std::array<double, 9> lindbloom{1.0478112,  0.0228866,  -0.0501270, 0.0295424, 0.9904844,
                                        -0.0170491, -0.0092345, 0.0150436,  0.7521316};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(m.m[i], lindbloom[i], kLindbloomTolerance) << i;
}

// CIECAM02's cone matrix M_CAT02 (CIE 159:2004, 4 decimals, as published); von Kries in that space:
// M⁻¹ · diag(ρ_dst/ρ_src) · M.
TEST(Adaptation, Cat02IsVonKriesInThePublishedConeSpace) {
  const Mat3 cat02{{0.7328, 0.4296, -0.1624, -0.7036, 1.6975, 0.0061, 0.0030, 0.0136, 0.9834}};
  const Xyz src = xyz_from_xy({0.3127, 0.3290}), dst = xyz_from_xy({0.32168, 0.33767});
  const Xyz cs = cat02 * RgbT<double>{src.X, src.Y, src.Z},
            cd = cat02 * RgbT<double>{dst.X, dst.Y, dst.Z};
  const Mat3 want = cat02.inverse() * Mat3::diagonal(cd.X / cs.X, cd.Y / cs.Y, cd.Z / cs.Z) * cat02;
  const Mat3 got = adaptation_matrix(Adaptation::Cat02, src, dst);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(got.m[i], want.m[i], 1e-12) << i;
}

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
  const Mat3 ours = rec709.xyz_to_rgb *
                    adaptation_matrix(Adaptation::Bradford, ap1.white, rec709.white) *
                    ap1.rgb_to_xyz;
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
  const auto rows = test::csv_file_rows(
      std::string(FL_SHARED_TESTDATA) + "/ciede2000_sharma2005.csv", {.skip_comments = true});
  ASSERT_FALSE(rows.empty()) << "missing shared test data";
  int pairs = 0;
  for (const auto& row : rows) {
    if (row[0] == "pair") continue;  // the header
    const auto v = test::csv_numbers(row);
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
