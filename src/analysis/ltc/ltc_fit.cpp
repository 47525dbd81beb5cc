// The LTC cell fit: the residuals and their Jacobian, the Ceres solve and the continuation over a
// table's cells (the lobe and the directions it is fitted on: ltc_samples.cpp).
#include "analysis/ltc/ltc_fit.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "analysis/ltc/ltc_samples.h"
#include "util/codegen.h"

namespace fl::analysis {

namespace {

// A problem's samples as columns, and the per-sample terms of the residuals at the last θ, which
// their Jacobian reuses. Columns let the compiler evaluate several samples per instruction; each
// sample's arithmetic is unchanged.
struct LtcColumns {
  std::vector<double> x, y, z, target, weight;
  std::vector<double> ox, oy, oz, inv_len2, dens, root, residual;
};
LtcColumns ltc_columns(const LtcProblem& pr) {
  LtcColumns c;
  const size_t n = pr.samples.size();
  for (auto* col : {&c.x, &c.y, &c.z, &c.target, &c.weight}) col->reserve(n);
  for (const auto& s : pr.samples) {
    c.x.push_back(s.x), c.y.push_back(s.y), c.z.push_back(s.z);
    c.target.push_back(s.target), c.weight.push_back(s.weight);
  }
  for (auto* col : {&c.ox, &c.oy, &c.oz, &c.inv_len2, &c.dens, &c.root, &c.residual})
    col->resize(n);
  return c;
}

// Residual k = d √|d| w with d = target − n_D D_LTC (ltc_density with θ = p = (m11, m22, m13,
// m31)).
FL_FLATTEN void ltc_residuals(double magnitude, const double* p, LtcColumns& c) {
  const double inv_beta = 1.0 / (p[0] - p[2] * p[3]), inv_m22 = 1.0 / p[1];
  const double p0 = p[0], p2 = p[2], p3 = p[3];
  const size_t n = c.x.size();
#pragma GCC ivdep
  for (size_t k = 0; k < n; ++k) {
    const double ox = (c.x[k] - p2 * c.z[k]) * inv_beta, oy = c.y[k] * inv_m22;
    const double oz = (p0 * c.z[k] - p3 * c.x[k]) * inv_beta;
    const double inv_len2 = 1.0 / (ox * ox + oy * oy + oz * oz);
    const double dens =
        oz > 0.0 ? oz * inv_beta * inv_m22 * inv_len2 * inv_len2 / std::numbers::pi : 0.0;
    const double d = c.target[k] - magnitude * dens;
    const double root = std::sqrt(std::abs(d));
    c.ox[k] = ox, c.oy[k] = oy, c.oz[k] = oz, c.inv_len2[k] = inv_len2, c.dens[k] = dens,
    c.root[k] = root;
    c.residual[k] = d * root * c.weight[k];
  }
}

// The Jacobian of ltc_residuals at the same θ, row k = ∂r_k/∂θ, from the terms it kept.
// With u = x − m13 z, t = m11 z − m31 x, β = m11 − m13 m31, o = (u/β, y/m22, t/β), L = ‖o‖²:
// D = t / (π m22 β² L²), so ∂ln D = ∂t/t − ∂m22/m22 − 2 ∂β/β − 2 ∂L/L with
// ∂L = 2 (o_x ∂u + o_z ∂t)/β − 2 (o_x² + o_z²) ∂β/β − 2 o_y² ∂m22/m22, where (∂u, ∂t, ∂β, ∂m22) is
// (0, z, 1, 0) for m11, (0, 0, 0, 1) for m22, (−z, 0, −m31, 0) for m13 and (0, −x, −m13, 0) for
// m31; and ∂r/∂D = −1.5 √|d| w n_D.
FL_FLATTEN void ltc_jacobian(double magnitude, const double* p, const LtcColumns& c, double* jac) {
  const double inv_beta = 1.0 / (p[0] - p[2] * p[3]), inv_m22 = 1.0 / p[1];
  const double p2 = p[2], p3 = p[3];
  const size_t n = c.x.size();
#pragma GCC ivdep
  for (size_t k = 0; k < n; ++k) {
    const double ox = c.ox[k], oy = c.oy[k], oz = c.oz[k], x = c.x[k], z = c.z[k];
    const double g = -1.5 * c.root[k] * c.weight[k] * magnitude * c.dens[k];
    const double inv_t = inv_beta / oz, s2 = 2.0 * (ox * ox + oz * oz) * inv_beta,
                 two_l = 2.0 * c.inv_len2[k];
    const double j0 = g * (z * inv_t - 2.0 * inv_beta - two_l * (2.0 * oz * z * inv_beta - s2));
    const double j1 = g * inv_m22 * (2.0 * two_l * oy * oy - 1.0);
    const double j2 = g * (2.0 * p3 * inv_beta - two_l * (s2 * p3 - 2.0 * ox * z * inv_beta));
    const double j3 =
        g * (-x * inv_t + 2.0 * p2 * inv_beta - two_l * (s2 * p2 - 2.0 * oz * x * inv_beta));
    const bool zero = c.dens[k] == 0.0;
    const double r0 = zero ? 0.0 : j0, r1 = zero ? 0.0 : j1, r2 = zero ? 0.0 : j2,
                 r3 = zero ? 0.0 : j3;
    jac[4 * k] = r0, jac[4 * k + 1] = r1, jac[4 * k + 2] = r2, jac[4 * k + 3] = r3;
  }
}

double sum_squared_residuals(const LtcProblem& pr, const LtcParams& p) {
  const double q[4] = {p.m11, p.m22, p.m13, p.m31};
  LtcColumns c = ltc_columns(pr);
  ltc_residuals(pr.magnitude, q, c);
  double sum = 0.0;
  for (const double r : c.residual) sum += r * r;
  return sum;
}

// ½ Σ r² estimates ½ ∫ |ρ cos − n_D D_LTC|³ dω / B₃; the Jacobian is analytic (ltc_jacobian).
// A step that would make A singular or flip it (β ≤ 0) is rejected as invalid.
// Ceres evaluates an accepted step's point up to three times (its line search, the step's cost,
// then the Jacobian there), so the cost keeps the terms of the last point it evaluated (columns_)
// and that point's Jacobian once computed, and evaluates a point again only when its parameters
// differ in a bit.
class LtcCost final : public ceres::CostFunction {
 public:
  explicit LtcCost(const LtcProblem& problem)
      : magnitude_(problem.magnitude),
        columns_(ltc_columns(problem)),
        jacobian_(4 * problem.samples.size()) {
    set_num_residuals(static_cast<int>(problem.samples.size()));
    mutable_parameter_block_sizes()->push_back(4);
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const double* p = parameters[0];
    if (!(p[0] - p[2] * p[3] > kLtcMinScale * p[0])) return false;
    if (!evaluated_ || std::memcmp(p, at_, sizeof(at_)) != 0) {
      ltc_residuals(magnitude_, p, columns_);
      std::copy(p, p + 4, at_);
      evaluated_ = true, has_jacobian_ = false;
    }
    std::copy(columns_.residual.begin(), columns_.residual.end(), residuals);
    if (jacobians && jacobians[0]) {
      if (!has_jacobian_) ltc_jacobian(magnitude_, p, columns_, jacobian_.data());
      has_jacobian_ = true;
      std::copy(jacobian_.begin(), jacobian_.end(), jacobians[0]);
    }
    return true;
  }

 private:
  double magnitude_;
  mutable LtcColumns columns_;            // the terms of the residuals at at_
  mutable std::vector<double> jacobian_;  // the Jacobian at at_ when has_jacobian_
  mutable double at_[4] = {0, 0, 0, 0};
  mutable bool evaluated_ = false, has_jacobian_ = false;
};

LtcParams clamp_to_bounds(const LtcParams& p) {
  return {
      std::clamp(p.m11, kLtcMinScale, kLtcMaxScale), std::clamp(p.m22, kLtcMinScale, kLtcMaxScale),
      std::clamp(p.m13, -kLtcMaxSkew, kLtcMaxSkew), std::clamp(p.m31, -kLtcMaxSkew, kLtcMaxSkew)};
}

// The largest parameter change, relative to the lobe's scale.
double relative_change(const LtcParams& a, const LtcParams& b) {
  return std::max({std::abs(b.m11 - a.m11) / a.m11, std::abs(b.m22 - a.m22) / a.m22,
                   std::abs(b.m13 - a.m13) / std::max(a.m11, std::abs(a.m13)),
                   std::abs(b.m31 - a.m31) / std::max(a.m11, std::abs(a.m31))});
}

LtcParams params_of(const fit::FitResult& r) {
  if (r.parameters.size() != 4) throw std::runtime_error("LTC solver returned no parameters");
  return clamp_to_bounds({r.parameters[0], r.parameters[1], r.parameters[2], r.parameters[3]});
}

}  // namespace

double ltc_objective(const LtcProblem& problem, const LtcParams& p) {
  return 0.5 * sum_squared_residuals(problem, p);
}

LtcParams extrapolate_ltc_start(const LtcParams& prev, const LtcParams& prev2) {
  const LtcParams e{2.0 * prev.m11 - prev2.m11, 2.0 * prev.m22 - prev2.m22,
                    2.0 * prev.m13 - prev2.m13, 2.0 * prev.m31 - prev2.m31};
  const bool valid =
      e.m11 > kLtcMinScale && e.m22 > kLtcMinScale && e.m11 - e.m13 * e.m31 > kLtcMinScale * e.m11;
  return valid ? clamp_to_bounds(e) : prev;
}

namespace {

// Rounds of the solver from one start (fit_ltc_cell).
struct Rounds {
  LtcParams params;
  fit::FitResult fit;
  int rounds = 0;
};
Rounds fit_rounds(double nov, double alpha, double magnitude, const LtcFrame& frame,
                  const Directions& ggx, const LtcPointSet& set, const LtcParams& start,
                  bool isotropic, const LtcSolver& solver) {
  Rounds out{start, {}, 0};
  while (out.rounds < kLtcMaxRounds) {
    const auto problem = assemble_problem(nov, alpha, magnitude, frame, ggx, set, out.params);
    out.fit = solver(problem, out.params, isotropic);
    const LtcParams q = params_of(out.fit);
    ++out.rounds;
    const bool settled = relative_change(out.params, q) <= kLtcRoundTolerance;
    out.params = q;
    if (settled) break;
  }
  return out;
}

// The point of the segment from `best` (held-out error `best_error`) to `target` nearest `target`
// whose error stays within `bound`: `target` itself when it is; otherwise the last of the steps of
// 1/kLtcContinuationSteps from `best` that is, refined by kLtcContinuationBisections bisections
// towards the first that is not (the walk stays in `best`'s valley).
struct Chosen {
  LtcParams params;
  double step = 0;  // the fraction of the way from best to target
};
Chosen toward_continuation(const LtcParams& best, const LtcParams& target, double bound,
                           const std::function<double(const LtcParams&)>& error) {
  auto at = [&](double s) {
    return LtcParams{best.m11 + s * (target.m11 - best.m11), best.m22 + s * (target.m22 - best.m22),
                     best.m13 + s * (target.m13 - best.m13),
                     best.m31 + s * (target.m31 - best.m31)};
  };
  if (error(target) <= bound) return {target, 1.0};
  double lo = 0.0, hi = 1.0;
  for (int k = 1; k < kLtcContinuationSteps; ++k) {
    const double s = static_cast<double>(k) / kLtcContinuationSteps;
    if (error(at(s)) > bound) {
      hi = s;
      break;
    }
    lo = s;
  }
  for (int k = 0; k < kLtcContinuationBisections; ++k) {
    const double s = 0.5 * (lo + hi);
    (error(at(s)) <= bound ? lo : hi) = s;
  }
  return {at(lo), lo};
}

}  // namespace

LtcCellPoints ltc_cell_points(int sample_sqrt) {
  return {point_set(stratified_midpoints(std::max(1, sample_sqrt))),
          point_set(hammersley_points(kLtcHeldOutSamples)),
          point_set(hammersley_points(kLtcNearEqualSamples))};
}

LtcCellFit fit_ltc_cell(double nov, double alpha, double magnitude, const brdf::Vec3& average_dir,
                        const std::vector<LtcParams>& starts, bool isotropic,
                        const LtcSolver& solver, int sample_sqrt, double near_equal_margin) {
  return fit_ltc_cell(nov, alpha, magnitude, average_dir, starts, isotropic, solver,
                      ltc_cell_points(sample_sqrt), near_equal_margin);
}

LtcCellFit fit_ltc_cell(double nov, double alpha, double magnitude, const brdf::Vec3& average_dir,
                        const std::vector<LtcParams>& starts, bool isotropic,
                        const LtcSolver& solver, const LtcCellPoints& points,
                        double near_equal_margin) {
  if (starts.empty()) throw std::invalid_argument("fit_ltc_cell needs a start");
  const brdf::Vec3 v = brdf::view_from_nov(nov);
  const LtcFrame frame = ltc_frame_from_average_direction(average_dir);
  const LtcPointSet& set = points.fit;
  const Directions ggx = ggx_half(v, alpha, set.disk);
  // The relative L3 error of an LTC on a point set whose GGX half is `judge_ggx`.
  auto judged = [&](const Directions& judge_ggx, const LtcPointSet& judge_set, const LtcParams& x) {
    return l3_errors(v, alpha, magnitude, judge_ggx, judge_set, {ltc_lobe(ltc_matrix(frame, x))})[0]
        .relative();
  };
  const Directions heldout_ggx = ggx_half(v, alpha, points.heldout.disk);
  auto heldout = [&](const LtcParams& x) { return judged(heldout_ggx, points.heldout, x); };
  LtcCellFit out;
  LtcParams best_start;
  out.start_heldout_error = std::numeric_limits<double>::infinity();
  for (const auto& s : starts) {
    const LtcParams c = clamp_to_bounds(s);
    const double e = heldout(c);
    if (e < out.start_heldout_error) best_start = c, out.start_heldout_error = e;
  }
  out.heldout_error = std::numeric_limits<double>::infinity();
  for (const auto& s : starts) {
    const auto r =
        fit_rounds(nov, alpha, magnitude, frame, ggx, set, clamp_to_bounds(s), isotropic, solver);
    const double e = heldout(r.params);
    ++out.fits;
    if (e < out.heldout_error)
      out.params = r.params, out.fit = r.fit, out.rounds = r.rounds, out.heldout_error = e;
    const bool rejected = out.heldout_error > out.start_heldout_error * (1.0 + kLtcHeldOutMargin);
    if (r.rounds < kLtcRetryRounds && !rejected) break;
  }
  out.kept_start = out.heldout_error > out.start_heldout_error * (1.0 + kLtcHeldOutMargin);
  if (out.kept_start) out.params = best_start, out.heldout_error = out.start_heldout_error;
  if (out.kept_start || !(near_equal_margin > 0.0)) return out;
  // The near-equal choice, judged on kLtcNearEqualSamples fresh directions.
  const Directions near_ggx = ggx_half(v, alpha, points.near_equal.disk);
  auto near_error = [&](const LtcParams& x) { return judged(near_ggx, points.near_equal, x); };
  const auto c =
      toward_continuation(out.params, clamp_to_bounds(starts.front()),
                          near_error(out.params) * (1.0 + near_equal_margin), near_error);
  if (c.step > 0.0)
    out.params = c.params, out.heldout_error = heldout(c.params), out.continuation_step = c.step;
  return out;
}

fit::FitResult fit_ltc_ceres(const LtcProblem& problem, const LtcParams& start, bool isotropic) {
  const LtcParams s0 = clamp_to_bounds(start);
  double p[4] = {s0.m11, s0.m22, s0.m13, s0.m31};
  ceres::Problem pr;
  pr.AddResidualBlock(new LtcCost(problem), nullptr, p);
  for (int i = 0; i < 4; ++i) {
    pr.SetParameterLowerBound(p, i, i < 2 ? kLtcMinScale : -kLtcMaxSkew);
    pr.SetParameterUpperBound(p, i, i < 2 ? kLtcMaxScale : kLtcMaxSkew);
  }
  if (isotropic) pr.SetManifold(p, new ceres::SubsetManifold(4, {2, 3}));

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.function_tolerance = 1e-7;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-6;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &pr, &summary);

  fit::FitResult r;
  r.parameters = {p[0], p[1], p[2], p[3]};
  r.cost = summary.final_cost;
  r.initial_cost = summary.initial_cost;
  r.iterations = static_cast<int>(summary.iterations.size());
  r.termination = ceres::TerminationTypeToString(summary.termination_type);
  r.usable = summary.IsSolutionUsable();
  r.starts = 1;
  return r;
}

fit::GradientCheck check_ltc_gradients(const LtcProblem& problem, const LtcParams& p) {
  const LtcCost cost(problem);
  const double q[4] = {p.m11, p.m22, p.m13, p.m31};
  const double* blocks[] = {q};
  const size_t n = problem.samples.size();
  std::vector<double> r(n), jac(4 * n);
  double* jacobians[] = {jac.data()};
  fit::GradientCheck out;
  if (!cost.Evaluate(blocks, r.data(), jacobians)) {
    out.report = "the cost function rejected the parameters";
    return out;
  }
  // Central differences of Σ r² with steps of 1e-5 of each parameter's scale,
  // Richardson-extrapolated.
  const double scale[4] = {p.m11, p.m22, std::max(p.m11, std::abs(p.m13)),
                           std::max(p.m11, std::abs(p.m31))};
  double analytic[4] = {0, 0, 0, 0}, numeric[4], largest = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (size_t k = 0; k < n; ++k) analytic[c] += 2.0 * r[k] * jac[4 * k + c];
    auto diff = [&](double h) {
      double a[4] = {q[0], q[1], q[2], q[3]}, b[4] = {q[0], q[1], q[2], q[3]};
      a[c] += h, b[c] -= h;
      return (sum_squared_residuals(problem, {a[0], a[1], a[2], a[3]}) -
              sum_squared_residuals(problem, {b[0], b[1], b[2], b[3]})) /
             (2.0 * h);
    };
    const double h = 1e-5 * scale[c];
    numeric[c] = (4.0 * diff(h) - diff(2.0 * h)) / 3.0;
    largest = std::max({largest, std::abs(analytic[c]), std::abs(numeric[c])});
  }
  for (int c = 0; c < 4; ++c) {
    out.max_relative_error = std::max(
        out.max_relative_error, std::abs(analytic[c] - numeric[c]) / std::max(largest, 1e-300));
    out.report +=
        fmt::format("d/dθ{}: analytic {:.10g}, numeric {:.10g}\n", c, analytic[c], numeric[c]);
  }
  out.ok = true;
  return out;
}

}  // namespace fl::analysis
