#pragma once
// Fitting a linearly transformed cosine (LTC) to the GGX lobe of one (n·v, α) cell
// (Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed
// Cosines"). Ceres stays inside ltc_fit.cpp; callers see LtcProblem, LtcParams and fit::FitResult.
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "brdf/ggx.h"
#include "fit/fit.h"

namespace fl::analysis {

// The free entries of the isotropic LTC matrix in its frame (X, Y, Z):
// M = [X Y Z] · A, A = [[m11, 0, m13], [0, m22, 0], [m31, 0, 1]] (row-major). Heitz's fitLTC.cpp
// fits m11, m22, m13 with the frame's Z on the lobe's average direction; m31 tilts the LTC's frame
// in the plane of incidence away from that direction. M is then any matrix of the form
// [[a, 0, b], [0, c, 0], [d, 0, e]] up to scale, the four entries the LTC texture stores, so the
// fit chooses from every LTC the texture can hold.
struct LtcParams {
  double m11 = 1.0, m22 = 1.0, m13 = 0.0, m31 = 0.0;
};

// Bounds of the fit: A stays invertible (m11, m22 > 0, and the fit keeps det = m22 (m11 − m13 m31)
// > 0) and the lobe stays representable. The lower bound of m11 and m22 is ltc_code's
// (fit/fitLTC.cpp, FitLTC::update clamps them at 1e-7); α itself is clamped at 1e-5
// (analysis::kLtcMinAlpha).
constexpr double kLtcMinScale = 1e-7;
constexpr double kLtcMaxScale = 1e3;
constexpr double kLtcMaxSkew = 1e3;

// The LTC frame of an isotropic lobe: Z is the lobe's average direction (in the xz-plane), Y = (0,
// 1, 0) and X = Y × Z = (Z.z, 0, −Z.x).
struct LtcFrame {
  brdf::Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
};
LtcFrame ltc_frame_from_average_direction(const brdf::Vec3& average_dir);

// Heitz et al. 2016, eq. 3: the LTC density D(ω) = D_o(ω_o) ∂ω_o/∂ω with ω_o = M⁻¹ω/‖M⁻¹ω‖,
// D_o(ω_o) = max(0, z_o)/π (the clamped cosine, unit integral) and ∂ω_o/∂ω = |M⁻¹| / ‖M⁻¹ω‖³.
// In frame coordinates (x, y, z) of a unit ω, with β = m11 − m13 m31 the determinant of A's
// xz-block: M⁻¹ω = ((x − m13 z)/β, y/m22, (m11 z − m31 x)/β) and |M⁻¹| = 1/(m22 β), so D(ω) =
// max(0, (M⁻¹ω)_z) / (π m22 β ‖M⁻¹ω‖⁴).
double ltc_density(const LtcParams& p, double x, double y, double z);

// The full matrix M (row-major, world coordinates) and its inverse.
struct LtcMatrix {
  std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};
  double operator()(int r, int c) const { return m[3 * r + c]; }
};
LtcMatrix ltc_matrix(const LtcFrame& frame, const LtcParams& p);
LtcMatrix inverse(const LtcMatrix& a);

// An LTC in world coordinates given by any invertible M (a fitted cell's ltc_matrix, or a published
// table's matrix). M's scale cancels: the density depends on the direction of M⁻¹ω only.
struct LtcLobe {
  LtcMatrix m, m_inv;
  double abs_det_m_inv = 1;
};
LtcLobe ltc_lobe(const LtcMatrix& m);
// Heitz et al. 2016, eq. 3 with D_o = max(0, z_o)/π: D(ω) = max(0, (M⁻¹ω)_z) |M⁻¹| / (π ‖M⁻¹ω‖⁴).
double ltc_lobe_density(const LtcLobe& lobe, const brdf::Vec3& w);
// ω = M ω_o / ‖M ω_o‖ with ω_o drawn from the clamped cosine (cos θ_o = √u1, φ_o = 2π u2); its
// density is ltc_lobe_density.
brdf::Vec3 sample_ltc_lobe(const LtcLobe& lobe, double u1, double u2);

// The density of l = reflect(v, h) with h drawn from the GGX visible normals of v
// (brdf::ggx_vndf_reflection_pdf at h = normalize(v + l)); zero where h is below the surface.
double ggx_vndf_direction_pdf(const brdf::Vec3& v, const brdf::Vec3& l, double alpha);

// The error of an LTC against the GGX lobe it stands for, Heitz et al. 2016's fitting error
// (ltc_code fit/fitLTC.cpp, computeError): E₃ = ∫ |ρ cos − n_D D_LTC|³ dω over the sphere,
// estimated by multiple importance sampling of `samples` GGX visible-normal directions and
// `samples` LTC directions with the balance heuristic, each direction contributing f /
// (samples·(p_vndf + p_ltc)). The directions come from the Hammersley set of `samples` points, not
// from the stratified midpoints a fit uses, so the estimate is held out. B₃ = ∫ (ρ cos)³ dω by the
// same directions; relative() = (E₃ / B₃)^⅓ is scale-free, comparable across cells.
struct LtcL3Error {
  double error = 0, lobe = 0;
  double relative() const { return lobe > 0.0 ? std::cbrt(error / lobe) : 0.0; }
};
LtcL3Error ltc_l3_error(double nov, double alpha, double magnitude, const LtcLobe& lobe,
                        int samples);
// The same for several LTCs of one cell; the GGX directions are shared.
std::vector<LtcL3Error> ltc_l3_errors(double nov, double alpha, double magnitude,
                                      const std::vector<LtcLobe>& lobes, int samples);

// One fixed direction of the fit, in LTC frame coordinates, with the lobe value there.
struct LtcSample {
  double x = 0, y = 0, z = 0;
  double target = 0;  // ρ·cos of the GGX lobe (no Fresnel)
  double weight =
      0;  // 1/√(n (p_vndf + p_proposal) B₃): the MIS weight, normalized by the lobe's L3 norm
};

// What one cell's fit needs. The objective is Heitz et al. 2016's L3 error ∫ |ρ cos − n_D·D_LTC|³
// dω relative to B₃ = ∫ (ρ cos)³ dω, estimated with n = sample_sqrt² fixed directions drawn from
// the GGX visible normals and n drawn from a proposal LTC (multiple importance sampling, balance
// heuristic: each direction weighs 1/(n (p_vndf + p_proposal))). Sampling the LTC itself, as
// Heitz's fitLTC.cpp does, puts directions wherever the LTC has mass, so a lobe cannot hide between
// the directions. Residual k = d_k √|d_k| · w_k with d_k = ρ cos(ω_k) − n_D D_LTC(ω_k): ½ Σ r² = ½
// E₃ / B₃, a least-squares problem for Ceres. It is sharpest near the proposal.
struct LtcProblem {
  double nov = 1, alpha = 1;
  double magnitude = 1;  // n_D: the LTC is scaled to the lobe's integral
  LtcFrame frame;
  LtcParams proposal;
  std::vector<LtcSample> samples;
};
// sample_sqrt² directions from each strategy (stratified midpoints (i + ½)/k). The estimate is
// unbiased for every LTC whose support the proposal or the visible normals cover (the proposal's
// hemisphere tilts with m31, so fit_ltc_cell redraws the proposal at the fit).
constexpr int kLtcDefaultSampleSqrt = 16;
LtcProblem make_ltc_problem(double nov, double alpha, double magnitude,
                            const brdf::Vec3& average_dir, const LtcParams& proposal,
                            int sample_sqrt = kLtcDefaultSampleSqrt);

// ½ Σ r² over the problem's residuals (the Ceres cost of the same parameters): half the in-sample
// E₃ / B₃.
double ltc_objective(const LtcProblem& problem, const LtcParams& p);

// One solve on a problem's fixed directions from `start`; with `isotropic`, m13 and m31 are held at
// their start values (the lobe at normal incidence is rotationally symmetric).
// fit::FitResult::parameters = {m11, m22, m13, m31}.
using LtcSolver =
    std::function<fit::FitResult(const LtcProblem&, const LtcParams& start, bool isotropic)>;
// Ceres, Levenberg–Marquardt within the bounds above.
fit::FitResult fit_ltc_ceres(const LtcProblem& problem, const LtcParams& start, bool isotropic);
// The fit's analytic Jacobian at `p` through the gradient it gives, 2 Jᵀr = ∇ Σ r², against central
// differences of Σ r² (the residuals d √|d| are not twice differentiable where d = 0, so
// differences of single residuals are inaccurate there; Σ |d|³ is). max_relative_error is relative
// to the largest gradient component; the report lists both gradients.
fit::GradientCheck check_ltc_gradients(const LtcProblem& problem, const LtcParams& p);

// The start for a cell from the two cells before it along a row: the linear extrapolation
// 2·prev − prev2, or prev where that is not a valid LTC (m11, m22 or m11 − m13 m31 not positive).
LtcParams extrapolate_ltc_start(const LtcParams& prev, const LtcParams& prev2);

// A cell's fit. From a start, rounds of `solver`, each on the fixed GGX directions and directions
// drawn from the previous round's LTC (the first from the start's), until no parameter moves by
// more than kLtcRoundTolerance (at most kLtcMaxRounds). The starts (the continuation of the
// neighbouring cells first) are fitted in order; the next is tried only when a fit needed
// kLtcRetryRounds rounds or more (its optimum was far from its start, where the first proposals
// sample it poorly) or was rejected. The held-out check, on kLtcHeldOutSamples fresh directions
// (the Hammersley set of ltc_l3_errors): the fit with the lowest held-out error is kept unless it
// is worse than the best start by more than kLtcHeldOutMargin, and then the cell keeps that start.
// The near-equal choice (near_equal_margin > 0, a fraction of the error): where the held-out error
// is flat along a valley, the fit's end point within it depends on where the solver stopped, and
// neighbouring cells may step far apart in the texture though the continuation (the first start) is
// nearly as good. Among the LTCs on the segment from the kept fit to the continuation whose
// held-out error, on kLtcNearEqualSamples fresh directions, stays within (1 + near_equal_margin) of
// the fit's, the cell takes the one nearest the continuation: the continuation itself when it is
// within, else the last of steps of 1/kLtcContinuationSteps from the fit that is, refined by
// kLtcContinuationBisections bisections (a walk, so the choice stays in the fit's valley).
// heldout_error is then the chosen LTC's (kLtcHeldOutSamples directions); a kept start is kept.
constexpr int kLtcMaxRounds = 8;
constexpr int kLtcRetryRounds = 3;
constexpr double kLtcRoundTolerance = 1e-2;
constexpr int kLtcHeldOutSamples = 256;
// The held-out estimates share their GGX directions; below this their difference is sampling noise.
constexpr double kLtcHeldOutMargin = 0.01;
constexpr int kLtcNearEqualSamples = 2048;
constexpr int kLtcContinuationSteps = 8;
constexpr int kLtcContinuationBisections = 3;
struct LtcCellFit {
  LtcParams params;
  fit::FitResult fit;       // of the kept fit's last round
  int rounds = 0;           // of the kept fit
  int fits = 0;             // starts fitted
  bool kept_start = false;  // the held-out check rejected every fit
  double heldout_error = 0,
         start_heldout_error = 0;  // ltc_l3_error(...).relative() of the result and the best start
  double continuation_step =
      0;  // the near-equal choice's way from the fit to the continuation (0: the fit)
};
LtcCellFit fit_ltc_cell(double nov, double alpha, double magnitude, const brdf::Vec3& average_dir,
                        const std::vector<LtcParams>& starts, bool isotropic,
                        const LtcSolver& solver = fit_ltc_ceres,
                        int sample_sqrt = kLtcDefaultSampleSqrt, double near_equal_margin = 0.0);

// The view-independent part of a direction set's points: the unit-disk points of its GGX half
// (brdf::disk_point) and the clamped-cosine directions of its LTC half (sample_ltc_lobe before M).
struct LtcPointSet {
  std::vector<brdf::DiskPoint> disk;
  std::vector<brdf::Vec3> cosine;
};
// The point sets of fit_ltc_cell (sample_sqrt² stratified midpoints for the fit, kLtcHeldOutSamples
// and kLtcNearEqualSamples Hammersley points), made once and shared by every cell of a table.
struct LtcCellPoints {
  LtcPointSet fit, heldout, near_equal;
};
LtcCellPoints ltc_cell_points(int sample_sqrt = kLtcDefaultSampleSqrt);
// fit_ltc_cell with its point sets made beforehand; the same result.
LtcCellFit fit_ltc_cell(double nov, double alpha, double magnitude, const brdf::Vec3& average_dir,
                        const std::vector<LtcParams>& starts, bool isotropic,
                        const LtcSolver& solver, const LtcCellPoints& points,
                        double near_equal_margin);

}  // namespace fl::analysis
