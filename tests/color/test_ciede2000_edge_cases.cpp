// CIEDE2000 hue-angle edge cases (Sharma, Wu & Dalal 2005): achromatic sides, hue differences of
// exactly 180°, hues crossing 0°, float against double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "color/lab.h"

namespace {

using fl::color::Lab;
using fl::color::LabT;

constexpr double kPi = 3.14159265358979323846;
constexpr double kExact = 1e-12;       // closed forms evaluated in double
constexpr double kFloatDe2000 = 2e-4;  // float vs double: ΔE2000 (units of ΔE; measured 5.8e-5)

// ---------------- CIEDE2000 hue-angle edge cases ----------------

// CIEDE2000's T(h̄') weighting (Sharma et al. 2005, eq. 15), degrees.
double t_weight(double h) {
  const double r = kPi / 180.0;
  return 1 - 0.17 * std::cos((h - 30) * r) + 0.24 * std::cos(2 * h * r) +
         0.32 * std::cos((3 * h + 6) * r) - 0.20 * std::cos((4 * h - 63) * r);
}
// G for two colours of the same chroma C (eq. 4), and the a' scale 1 + G.
double a_scale(double chroma) {
  const double c7 = std::pow(chroma, 7);
  return 1.0 + 0.5 * (1.0 - std::sqrt(c7 / (c7 + std::pow(25.0, 7))));
}
// Equal L* and C' : ΔE00 = |ΔH'|/S_H (ΔL' = ΔC' = 0, so the rotation term vanishes).
double de_pure_hue(double c_prime, double dh_deg, double h_bar_deg) {
  const double dH = 2.0 * c_prime * std::sin(dh_deg * kPi / 360.0);
  return std::abs(dH) / (1.0 + 0.015 * c_prime * t_weight(h_bar_deg));
}

TEST(HardCasesDe2000, BothAchromatic) {
  // a = b = 0: only lightness counts; S_L = 1 + 0.015(L̄ − 50)²/√(20 + (L̄ − 50)²).
  const Lab a{50.0, 0.0, 0.0}, b{60.0, 0.0, 0.0};
  const double sl = 1.0 + 0.015 * 25.0 / std::sqrt(45.0);
  EXPECT_NEAR(fl::color::ciede2000(a, b), 10.0 / sl, kExact);
  EXPECT_NEAR(fl::color::ciede2000(b, a), 10.0 / sl, kExact);
  EXPECT_EQ(fl::color::ciede2000(a, a), 0.0);
  EXPECT_TRUE(std::isfinite(fl::color::ciede2000(LabT<float>{0, 0, 0}, LabT<float>{0, 0, 0})));
}

TEST(HardCasesDe2000, OneAchromaticSideUsesTheOtherHue) {
  // C1' = 0: the hue difference is 0 and h̄' = h1' + h2' (Sharma eq. 10, 14). Pure chroma change.
  const double c = 20.0, s = a_scale(c / 2.0);
  const Lab grey{50.0, 0.0, 0.0}, red{50.0, c, 0.0};  // h' = 0
  const double cp = s * c;                            // C2' (b = 0)
  const double want = cp / (1.0 + 0.045 * cp / 2.0);  // ΔC'/S_C with C̄' = cp/2; ΔH' = 0
  EXPECT_NEAR(fl::color::ciede2000(grey, red), want, 1e-9);
  EXPECT_NEAR(fl::color::ciede2000(red, grey), want, 1e-9);
}

TEST(HardCasesDe2000, HueDifferenceOfExactly180Degrees) {
  // h1' = 0°, h2' = 180°: |Δh'| = 180 takes the "≤ 180" branch, h̄' = 90°, ΔH' = 2C'.
  for (double c : {1.0, 10.0, 40.0}) {
    const Lab p{50.0, c, 0.0}, q{50.0, -c, 0.0};
    const double cp = a_scale(c) * c;
    const double want = de_pure_hue(cp, 180.0, 90.0);
    EXPECT_NEAR(fl::color::ciede2000(p, q), want, 1e-9) << c;
    EXPECT_NEAR(fl::color::ciede2000(q, p), want, 1e-9) << c;  // −180° the same
  }
  // Same along b: h' = 90° and 270°; |Δh'| = 180, h̄' = 180°.
  const Lab p{50.0, 0.0, 10.0}, q{50.0, 0.0, -10.0};
  EXPECT_NEAR(fl::color::ciede2000(p, q), de_pure_hue(10.0, 180.0, 180.0), 1e-9);
  EXPECT_NEAR(fl::color::ciede2000(q, p), de_pure_hue(10.0, 180.0, 180.0), 1e-9);
}

TEST(HardCasesDe2000, HuesCrossingZero) {
  // h' = ±h around 0/360 (e.g. 358° and 2°): Δh' = 2h, not 360 − 2h, and h̄' = 0 (≡ 360), not 180.
  for (double h_deg : {0.5, 1.0, 5.0, 30.0, 89.0}) {
    // (a, ±b) share C, hence G and C'; h' = ±atan2(b, (1 + G)a).
    const double c = 30.0;
    const double a = c * std::cos(h_deg * kPi / 180.0), b = c * std::sin(h_deg * kPi / 180.0);
    const double s = a_scale(c);
    const double cp = std::hypot(s * a, b), hp = std::atan2(b, s * a) * 180.0 / kPi;
    const Lab p{60.0, a, -b}, q{60.0, a, b};
    const double want = de_pure_hue(cp, 2.0 * hp, 0.0);
    EXPECT_NEAR(fl::color::ciede2000(p, q), want, 1e-9) << h_deg;
    EXPECT_NEAR(fl::color::ciede2000(q, p), want, 1e-9) << h_deg;
    // Float follows double.
    EXPECT_NEAR(fl::color::ciede2000(LabT<float>{60.0f, float(a), float(-b)},
                                     LabT<float>{60.0f, float(a), float(b)}),
                want, kFloatDe2000)
        << h_deg;
  }
}

TEST(HardCasesDe2000, FloatAgreesWithDoubleOverAGridOfColourPairs) {
  double worst = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      for (double dl : {0.0, 3.0})
        for (double c1 : {0.0, 2.0, 40.0}) {
          // ΔE00 is discontinuous where |h1' − h2'| crosses 180° (h̄' jumps by 180°; Sharma et al.
          // 2005 §3): float and double may land on either side there, so those pairs are skipped.
          const double h1 = 30.0 * i, h2 = 30.0 * j + (j % 2 ? 0.5 : 0.0);
          if (std::abs(std::abs(h1 - h2) - 180.0) < 1.0) continue;
          const LabT<float> pf{50.0f, float(c1 * std::cos(h1 * kPi / 180)),
                               float(c1 * std::sin(h1 * kPi / 180))};
          const LabT<float> qf{float(50.0 + dl), float(25.0 * std::cos(h2 * kPi / 180)),
                               float(25.0 * std::sin(h2 * kPi / 180))};
          const double d = fl::color::ciede2000(Lab{pf.L, pf.a, pf.b}, Lab{qf.L, qf.a, qf.b});
          const float f = fl::color::ciede2000(pf, qf);
          ASSERT_TRUE(std::isfinite(d) && std::isfinite(f));
          worst = std::max(worst, std::abs(d - f));
        }
  EXPECT_LE(worst, kFloatDe2000);
}

}  // namespace
