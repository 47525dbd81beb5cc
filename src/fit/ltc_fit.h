#pragma once
// Fitting a linearly transformed cosine (LTC) to the GGX lobe of one (n·v, α) cell
// (Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed
// Cosines"). Ceres stays inside ltc_fit.cpp; callers see LtcProblem, LtcParams and FitResult.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "brdf/ggx.h"
#include "fit/fit.h"

namespace fl::fit {

// The free entries of the isotropic LTC matrix in its frame (X, Y, Z):
// M = [X Y Z] · A, A = [[m11, 0, m13], [0, m22, 0], [0, 0, 1]] (row-major), as in Heitz's fitLTC.cpp.
struct LtcParams {
  double m11 = 1.0, m22 = 1.0, m13 = 0.0;
};

// Bounds of the fit: A stays invertible (m11, m22 > 0) and the lobe stays representable.
constexpr double kLtcMinScale = 1e-7;
constexpr double kLtcMaxScale = 1e3;
constexpr double kLtcMaxSkew = 1e3;

// The LTC frame of an isotropic lobe: Z is the lobe's average direction (in the xz-plane), Y = (0, 1, 0)
// and X = Y × Z = (Z.z, 0, −Z.x).
struct LtcFrame {
  brdf::Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
};
LtcFrame ltc_frame_from_average_direction(const brdf::Vec3& average_dir);

// Heitz et al. 2016, eq. 3: the LTC density D(ω) = D_o(ω_o) ∂ω_o/∂ω with ω_o = M⁻¹ω/‖M⁻¹ω‖,
// D_o(ω_o) = max(0, z_o)/π (the clamped cosine, unit integral) and ∂ω_o/∂ω = |M⁻¹| / ‖M⁻¹ω‖³.
// In frame coordinates (x, y, z) of a unit ω: M⁻¹ω = ((x − m13 z)/m11, y/m22, z), |M⁻¹| = 1/(m11 m22),
// so D(ω) = max(0, z) / (π m11 m22 ‖M⁻¹ω‖⁴).
template <class T>
T ltc_density(const T& m11, const T& m22, const T& m13, double x, double y, double z) {
  if (z <= 0.0) return T(0.0);
  const T ox = (x - m13 * z) / m11;
  const T oy = y / m22;
  const T len2 = ox * ox + oy * oy + z * z;
  return z / (std::numbers::pi * m11 * m22 * len2 * len2);
}

// The full matrix M (row-major, world coordinates) and its inverse.
struct LtcMatrix {
  std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};
  double operator()(int r, int c) const { return m[3 * r + c]; }
};
LtcMatrix ltc_matrix(const LtcFrame& frame, const LtcParams& p);
LtcMatrix inverse(const LtcMatrix& a);

// One fixed direction of the fit, in LTC frame coordinates, with the lobe value there.
struct LtcSample {
  double x = 0, y = 0, z = 0;
  double target = 0;  // ρ·cos of the GGX lobe (no Fresnel)
  double weight = 0;  // 1/√(q·count), q the mixture density the direction was drawn from
};

// What one cell's fit needs. The objective is the L2 error ∫ (ρ cos − n_D·D_LTC)² dω, estimated
// with fixed directions drawn half from the GGX visible-normal distribution and half uniformly on
// the sphere (multiple importance sampling with the balance heuristic, q = ½ p_vndf + ½/(4π)).
// Heitz's reference minimizes an L3 error with Nelder–Mead; an L2 error makes it a least-squares
// problem that Ceres solves directly.
struct LtcProblem {
  double nov = 1, alpha = 1;
  double magnitude = 1;  // n_D: the LTC is scaled to the lobe's integral
  LtcFrame frame;
  std::vector<LtcSample> samples;
};
// sample_sqrt² directions from each strategy (stratified midpoints (i + ½)/k).
constexpr int kLtcDefaultSampleSqrt = 24;
LtcProblem make_ltc_problem(double nov, double alpha, double magnitude, const brdf::Vec3& average_dir,
                            int sample_sqrt = kLtcDefaultSampleSqrt);

// ½ Σ r² over the problem's residuals (the Ceres cost of the same parameters).
double ltc_objective(const LtcProblem& problem, const LtcParams& p);
// Relative L2 error of the fitted lobe: √(Σ r² / Σ (target·weight)²).
double ltc_fit_error(const LtcProblem& problem, const LtcParams& p);

// Fits one cell with Ceres (Levenberg–Marquardt, bounds above) from `start`. With `isotropic`, m13
// is held at its start value (the lobe at normal incidence is rotationally symmetric).
// FitResult::parameters = {m11, m22, m13}.
FitResult fit_ltc_ceres(const LtcProblem& problem, const LtcParams& start, bool isotropic);

}  // namespace fl::fit
