// Linearly transformed cosines (fit/ltc_fit.h): the density against its definition, the matrix
// and its inverse, and the Ceres fit on a target it can represent exactly (a known answer).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "fit/ltc_fit.h"
#include "ggx_reference.h"
#include "quadrature.h"

namespace fl::fit {
namespace {

namespace ref = test::ggx_ref;

// A smooth density of unit integral by panel quadrature (measured ≤ 7e-12).
constexpr double kUnitIntegralTolerance = 1e-9;
// Two closed forms of the same density, and a matrix product: only rounding.
constexpr double kClosedFormTolerance = 1e-12;
// Parameters recovered from an exactly representable target.
constexpr double kRecoveredParamTolerance = 1e-6;

const std::vector<LtcParams> kParams = {{1.0, 1.0, 0.0}, {0.3, 0.3, 0.0}, {0.5, 0.9, 0.4},
                                        {2.0, 1.3, -0.8}, {0.4, 0.6, 1.2}};

brdf::Vec3 direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Over the frame's upper hemisphere, its support (A keeps z ≥ 0).
TEST(LtcDensity, IntegratesToOne) {
  for (const auto& p : kParams) {
    const double s = test::integrate_sphere(
        [&](double x, double y, double z) { return ltc_density(p.m11, p.m22, p.m13, x, y, z); },
        std::numbers::pi / 2, std::min(p.m11, p.m22));
    EXPECT_NEAR(s, 1.0, kUnitIntegralTolerance) << p.m11 << " " << p.m22 << " " << p.m13;
  }
}

// Heitz et al. 2016, eq. 3 evaluated with the world matrix's inverse equals the closed form in the
// frame, for frames tilted like the lobes of views away from the normal.
TEST(LtcDensity, MatchesTheTransformedCosineOfTheWorldMatrix) {
  for (double tilt : {0.0, 0.3, 0.9, 1.4}) {
    const LtcFrame frame = ltc_frame_from_average_direction({-std::sin(tilt), 0.0, std::cos(tilt)});
    for (const auto& p : kParams) {
      const LtcMatrix m = ltc_matrix(frame, p), m_inv = inverse(m);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          double s = 0;
          for (int k = 0; k < 3; ++k) s += m(r, k) * m_inv(k, c);
          EXPECT_NEAR(s, r == c ? 1.0 : 0.0, kClosedFormTolerance);
        }
      for (int a = 0; a < 12; ++a)
        for (int b = 0; b < 12; ++b) {
          const brdf::Vec3 w = direction((b + 0.5) * std::numbers::pi / 12, (a + 0.5) * std::numbers::pi / 6);
          const double fx = brdf::dot(w, frame.x), fy = brdf::dot(w, frame.y), fz = brdf::dot(w, frame.z);
          const double closed = ltc_density(p.m11, p.m22, p.m13, fx, fy, fz);
          EXPECT_NEAR(ref::ltc_from_inverse(m_inv.m, w), closed, kClosedFormTolerance * std::max(1.0, closed))
              << tilt << " " << a << "," << b;
        }
    }
  }
}

// A problem whose target is itself an LTC: the fit must find its parameters from another start.
TEST(LtcFit, RecoversTheParametersOfAnExactlyRepresentableTarget) {
  struct Case {
    double nov, alpha;
    LtcParams truth;
    bool isotropic;
  };
  for (const Case& c : std::vector<Case>{{1.0, 0.5, {0.45, 0.45, 0.0}, true},
                                         {0.7, 0.4, {0.35, 0.5, 0.2}, false},
                                         {0.3, 0.8, {0.9, 0.7, -0.3}, false}}) {
    const double magnitude = 0.8;
    const brdf::Vec3 mirror{-std::sqrt(1 - c.nov * c.nov), 0.0, c.nov};
    LtcProblem pr = make_ltc_problem(c.nov, c.alpha, magnitude, mirror);
    for (auto& s : pr.samples) s.target = magnitude * ltc_density(c.truth.m11, c.truth.m22, c.truth.m13, s.x, s.y, s.z);
    const FitResult r = fit_ltc_ceres(pr, {1.0, 1.0, 0.0}, c.isotropic);
    ASSERT_TRUE(r.usable) << r.termination;
    ASSERT_EQ(r.parameters.size(), 3u);
    EXPECT_NEAR(r.parameters[0], c.truth.m11, kRecoveredParamTolerance) << c.nov;
    EXPECT_NEAR(r.parameters[1], c.truth.m22, kRecoveredParamTolerance) << c.nov;
    EXPECT_NEAR(r.parameters[2], c.truth.m13, kRecoveredParamTolerance) << c.nov;
    EXPECT_NEAR(ltc_fit_error(pr, {r.parameters[0], r.parameters[1], r.parameters[2]}), 0.0, kRecoveredParamTolerance);
  }
}

}  // namespace
}  // namespace fl::fit
