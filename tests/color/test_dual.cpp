// color::Dual: values bit for bit those of the double computation, and derivatives of the model
// fits' ΔE2000 residuals over RGB against central finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "color/dual.h"
#include "color/lab.h"
#include "color/residual_fixtures.h"

namespace {

using fl::color::Dual;
using fl::color::Lab;
using fl::color::LabConverter;
using fl::color::Rgb;
using D3 = Dual<3>;

const LabConverter& kToLab = fl::test::kRec709ToLab;

// Five-point central differences, (8(f(x+h) − f(x−h)) − (f(x+2h) − f(x−2h))) / 12h, err by about
// h⁴·f⁽⁵⁾/30 plus rounding of about 1e-16/h times the residuals' scale (up to 1e3 near grey, where
// the hue turns fast). At h = 1e-5 both stay under 1e-7 here (measured 1.4e-8; with h = 1e-4 the h⁴
// term is 1.5e-4).
constexpr double kStep = 1e-5;
constexpr double kFiniteDifference = 1e-7;  // relative to max(1, |derivative|)

void residuals_double(const Lab& truth, const Rgb& rgb, double* r) {
  fl::color::ciede2000_residuals(truth, kToLab(rgb), r);
}

void residuals_dual(const Lab& truth, const Rgb& rgb, D3* r) {
  fl::test::residuals_dual(truth, rgb, r);
}

// Reflectance-like RGB and a truth colour near the model's (the fits' situation), plus far pairs.
struct Case {
  Lab truth;
  Rgb rgb;
};
std::vector<Case> cases() {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> u(0.002, 1.0), near(-0.02, 0.02);
  std::vector<Case> out;
  for (int i = 0; i < 2000; ++i) {
    const Rgb rgb{u(rng), u(rng), u(rng)};
    const Rgb other = i % 2 ? Rgb{rgb.r + near(rng), rgb.g + near(rng), rgb.b + near(rng)}
                            : Rgb{u(rng), u(rng), u(rng)};
    out.push_back({kToLab(other), rgb});
  }
  out.push_back({Lab{50.0, 0.0, 0.0},
                 Rgb{0.2, 0.2, 0.2}});  // both achromatic: derivatives are not checked there
  out.push_back({Lab{1.0, 0.5, -0.3},
                 Rgb{0.001, 0.0015, 0.0008}});  // the model in the cube root's linear toe
  return out;
}

TEST(Dual, ResidualValuesAreTheDoublePathsBitForBit) {
  for (const auto& c : cases()) {
    double r[3];
    D3 rd[3];
    residuals_double(c.truth, c.rgb, r);
    residuals_dual(c.truth, c.rgb, rd);
    for (int q = 0; q < 3; ++q) EXPECT_EQ(rd[q].v, r[q]);
  }
}

// Near pairs only: far apart, the hue difference can cross ±180°, where ΔH' jumps.
TEST(Dual, ResidualDerivativesMatchCentralDifferences) {
  double worst = 0;
  const auto all = cases();
  for (size_t i = 1; i < all.size(); i += 2) {
    const Case& c = all[i];
    D3 rd[3];
    residuals_dual(c.truth, c.rgb, rd);
    for (int k = 0; k < 3; ++k) {
      double f[4][3];  // at −2h, −h, +h, +2h
      const double at[4] = {-2 * kStep, -kStep, kStep, 2 * kStep};
      for (int j = 0; j < 4; ++j) {
        Rgb x = c.rgb;
        x[k] += at[j];
        residuals_double(c.truth, x, f[j]);
      }
      for (int q = 0; q < 3; ++q) {
        const double fd = (8 * (f[2][q] - f[1][q]) - (f[3][q] - f[0][q])) / (12 * kStep);
        const double err = std::abs(rd[q].d[k] - fd) / std::max(1.0, std::abs(fd));
        worst = std::max(worst, err);
      }
    }
  }
  EXPECT_LT(worst, kFiniteDifference) << worst;
}

TEST(Dual, ElementaryRules) {
  const D3 x = D3::variable(0.7, 0), y = D3::variable(-1.3, 1);
  const D3 a = atan2(y, x);
  EXPECT_EQ(a.v, std::atan2(-1.3, 0.7));
  EXPECT_DOUBLE_EQ(a.d[0], 1.3 / (0.7 * 0.7 + 1.3 * 1.3));  // ∂/∂x atan2(y, x) = −y / (x² + y²)
  EXPECT_DOUBLE_EQ(a.d[1], 0.7 / (0.7 * 0.7 + 1.3 * 1.3));  // ∂/∂y = x / (x² + y²)
  const D3 q = x / y;
  EXPECT_EQ(q.v, 0.7 / -1.3);
  EXPECT_DOUBLE_EQ(q.d[0], 1.0 / -1.3);
  EXPECT_DOUBLE_EQ(q.d[1], -0.7 / (1.3 * 1.3));
  EXPECT_DOUBLE_EQ(cbrt(x).d[0], 1.0 / (3.0 * std::cbrt(0.49)));
  EXPECT_DOUBLE_EQ(sqrt(x).d[0], 0.5 / std::sqrt(0.7));
  EXPECT_DOUBLE_EQ(exp(y).d[1], std::exp(-1.3));
  EXPECT_DOUBLE_EQ(sin(x).d[0], std::cos(0.7));
  EXPECT_DOUBLE_EQ(cos(x).d[0], -std::sin(0.7));
  const D3 p = pow(x, D3::variable(2.5, 1));
  EXPECT_EQ(p.v, std::pow(0.7, 2.5));
  EXPECT_DOUBLE_EQ(p.d[0], 2.5 * std::pow(0.7, 1.5));            // ∂/∂x xʸ = y·xʸ⁻¹
  EXPECT_DOUBLE_EQ(p.d[1], std::log(0.7) * std::pow(0.7, 2.5));  // ∂/∂y xʸ = ln x·xʸ
  EXPECT_TRUE(D3(1.5) == D3(1.5));
  EXPECT_EQ((2.0 - x).d[0], -1.0);
  EXPECT_EQ((x * y).d[2], 0.0);
}

}  // namespace
