// color::ciede2000_residuals_batch, the model fits' residuals and their derivatives over RGB in
// SIMD lanes, against the templated ciede2000_residuals (values in double, derivatives by
// color::Dual), against five-point central differences, and on every instruction set this CPU runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "color/ciede2000_batch.h"
#include "color/dual.h"
#include "color/lab.h"
#include "color/residual_fixtures.h"

namespace {

using fl::color::Dual;
using fl::color::Lab;
using fl::color::Rgb;
using D3 = Dual<3>;

const auto& kToLab = fl::test::kRec709ToLab;

// The vector formula differs from the template in its hue terms (hue vectors instead of atan2 and
// four cosines) and in its cube root, exp, sin and cos (Highway's polynomials, within a few ulps of
// libm's): residuals of up to about 100 agree within 1e-12, relative to max(1, |residual|)
// (measured 2.9e-13), and the derivatives, up to about 1e3 near grey, within 1e-9 relative to
// max(1, |derivative|) (measured 1.4e-11).
constexpr double kValue = 1e-12;
constexpr double kDerivative = 1e-9;
// Five-point differences at h = 1e-5 err by under 1e-7 here (see test_dual.cpp; measured 8.7e-9).
constexpr double kStep = 1e-5;
constexpr double kFiniteDifference = 1e-7;

struct Reference {
  double r[3];
  double d[3][3];  // d[q][c]
};
Reference reference(const Lab& truth, const Rgb& rgb) {
  D3 rd[3];
  fl::test::residuals_dual(truth, rgb, rd);
  Reference out{};
  for (int q = 0; q < 3; ++q) {
    out.r[q] = rd[q].v;
    for (int c = 0; c < 3; ++c) out.d[q][c] = rd[q].d[c];
  }
  return out;
}

struct Batch {
  std::vector<double> r, d;  // d[(3q + c)·n + i]
};
Batch batch(const std::vector<Lab>& truth, const std::vector<Rgb>& rgb,
            const std::string& target = "") {
  Batch out{std::vector<double>(3 * rgb.size()), std::vector<double>(9 * rgb.size())};
  if (target.empty())
    fl::color::ciede2000_residuals_batch(kToLab, truth, rgb, out.r, out.d);
  else
    fl::color::ciede2000_residuals_batch_on(target, kToLab, truth, rgb, out.r, out.d);
  return out;
}

// Reflectance-like RGB with a truth colour near it (a fit's situation) or anywhere; grey, toe and
// opposite-hue colours; an odd count, so that a tail is padded.
struct Cases {
  std::vector<Lab> truth;
  std::vector<Rgb> rgb;
};
Cases cases() {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> u(0.002, 1.0), near(-0.02, 0.02);
  Cases out;
  for (int i = 0; i < 3001; ++i) {
    const Rgb x{u(rng), u(rng), u(rng)};
    const Rgb other = i % 2 ? Rgb{x.r + near(rng), x.g + near(rng), x.b + near(rng)}
                            : Rgb{u(rng), u(rng), u(rng)};
    out.truth.push_back(kToLab(other));
    out.rgb.push_back(x);
  }
  out.truth.push_back(Lab{50.0, 0.0, 0.0});  // an achromatic truth: the reference decides the lane
  out.rgb.push_back(Rgb{0.3, 0.2, 0.1});
  out.truth.push_back(Lab{1.0, 0.5, -0.3});  // the model in the cube root's linear toe
  out.rgb.push_back(Rgb{0.001, 0.0015, 0.0008});
  out.truth.push_back(Lab{40.0, -20.0, -10.0});  // hues nearly opposite to the model's
  out.rgb.push_back(Rgb{0.4, 0.1, 0.05});
  return out;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::max(1.0, std::abs(b));
}

TEST(ResidualsBatch, ValuesAndDerivativesMatchTheTemplate) {
  const auto [truth, rgb] = cases();
  const size_t n = rgb.size();
  const auto b = batch(truth, rgb);
  double worst_value = 0, worst_derivative = 0;
  for (size_t i = 0; i < n; ++i) {
    const auto ref = reference(truth[i], rgb[i]);
    for (int q = 0; q < 3; ++q) {
      worst_value = std::max(worst_value, relative(b.r[3 * i + q], ref.r[q]));
      for (int c = 0; c < 3; ++c)
        worst_derivative =
            std::max(worst_derivative, relative(b.d[(3 * q + c) * n + i], ref.d[q][c]));
    }
  }
  EXPECT_LT(worst_value, kValue);
  EXPECT_LT(worst_derivative, kDerivative);
}

// Their squares sum to ΔE00² (the residuals' definition), checked against the plain ΔE00.
TEST(ResidualsBatch, SquaresSumToTheColourDifference) {
  const auto [truth, rgb] = cases();
  const auto b = batch(truth, rgb);
  for (size_t i = 0; i < rgb.size(); ++i) {
    const double de = fl::color::ciede2000(truth[i], kToLab(rgb[i]));
    const double sum =
        b.r[3 * i] * b.r[3 * i] + b.r[3 * i + 1] * b.r[3 * i + 1] + b.r[3 * i + 2] * b.r[3 * i + 2];
    EXPECT_NEAR(std::sqrt(sum), de, kValue * std::max(1.0, de)) << i;
  }
}

// Near pairs only: far apart, the hue difference can cross ±180°, where ΔH' jumps.
TEST(ResidualsBatch, DerivativesMatchCentralDifferences) {
  const auto [truth, rgb] = cases();
  const size_t n = rgb.size();
  const auto b = batch(truth, rgb);
  double worst = 0;
  for (size_t i = 1; i < 3001; i += 2) {
    for (int c = 0; c < 3; ++c) {
      double f[4][3];  // at −2h, −h, +h, +2h
      const double at[4] = {-2 * kStep, -kStep, kStep, 2 * kStep};
      for (int j = 0; j < 4; ++j) {
        Rgb x = rgb[i];
        x[c] += at[j];
        fl::color::ciede2000_residuals(truth[i], kToLab(x), f[j]);
      }
      for (int q = 0; q < 3; ++q) {
        const double fd = (8 * (f[2][q] - f[1][q]) - (f[3][q] - f[0][q])) / (12 * kStep);
        worst = std::max(worst, relative(b.d[(3 * q + c) * n + i], fd));
      }
    }
  }
  EXPECT_LT(worst, kFiniteDifference) << worst;
}

// Every instruction set, and every length up to two vectors of the widest (tails padded).
TEST(ResidualsBatch, EveryInstructionSetAndLength) {
  const auto [all_truth, all_rgb] = cases();
  for (const auto& target : fl::color::ciede2000_batch_targets()) {
    for (size_t n = 1; n <= 17; ++n) {
      const std::vector<Lab> truth(all_truth.end() - n, all_truth.end());
      const std::vector<Rgb> rgb(all_rgb.end() - n, all_rgb.end());
      const auto b = batch(truth, rgb, target);
      for (size_t i = 0; i < n; ++i) {
        const auto ref = reference(truth[i], rgb[i]);
        for (int q = 0; q < 3; ++q) {
          EXPECT_LT(relative(b.r[3 * i + q], ref.r[q]), kValue)
              << target << " n=" << n << " i=" << i;
          for (int c = 0; c < 3; ++c)
            EXPECT_LT(relative(b.d[(3 * q + c) * n + i], ref.d[q][c]), kDerivative)
                << target << " n=" << n;
        }
      }
    }
  }
}

// An achromatic truth goes to the reference, which the lane then returns exactly.
TEST(ResidualsBatch, AchromaticLanesAreTheReferences) {
  const std::vector<Lab> truth(5, Lab{50.0, 0.0, 0.0});
  const std::vector<Rgb> rgb{
      {0.3, 0.2, 0.1}, {0.2, 0.2, 0.2}, {0.1, 0.5, 0.2}, {0.7, 0.1, 0.6}, {0.05, 0.05, 0.4}};
  const auto b = batch(truth, rgb);
  for (size_t i = 0; i < rgb.size(); ++i) {
    const auto ref = reference(truth[i], rgb[i]);
    for (int q = 0; q < 3; ++q) {
      EXPECT_EQ(b.r[3 * i + q], ref.r[q]);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(b.d[(3 * q + c) * rgb.size() + i], ref.d[q][c]);
    }
  }
}

TEST(ResidualsBatch, RefusesMismatchedLengths) {
  const std::vector<Lab> truth(2);
  const std::vector<Rgb> rgb(2);
  std::vector<double> r(6), d(18);
  EXPECT_THROW(fl::color::ciede2000_residuals_batch(kToLab, truth, rgb, r, std::span(d).first(17)),
               std::invalid_argument);
  EXPECT_THROW(
      fl::color::ciede2000_residuals_batch_on("no such instruction set", kToLab, truth, rgb, r, d),
      std::invalid_argument);
}

}  // namespace
