#include "fit/fit.h"

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "color/ciede2000_batch.h"
#include "color/dual.h"
#include "fresnel/registry.h"
#include "util/codegen.h"

namespace fl::fit {
namespace {

using fresnel::Model;

// Three residuals per angle whose squares sum to ΔE2000² between the ground truth and the model's
// RGB (color::ciede2000_residuals), both in the working space's CIELAB, for every angle at once in
// SIMD lanes (color::ciede2000_residuals_batch). The Jacobian is formed by the chain rule: each
// channel differentiated over the parameters it reads (its own block and the shared ones, as a
// color::Dual of kChannelLanes lanes whose value is the double computation's, bit for bit; a
// channel never reads another channel's block, so those entries are zero), and the residuals over
// RGB from the same batch.
template <class Unit>
class ModelCurveCost : public ceres::CostFunction {
 public:
  static constexpr int kPer = static_cast<int>(Unit::kChannelParams.size());
  static constexpr int kShared = static_cast<int>(Unit::kSharedParams.size());
  static constexpr int kParams = fresnel::unit_param_count<Unit>();
  static constexpr int kChannelLanes = kPer + kShared;
  using ChannelDual = color::Dual<kChannelLanes>;

  explicit ModelCurveCost(const CurveTarget* target)
      : target_(target),
        rgb_(target->cos_thetas.size()),
        channels_(target->cos_thetas.size()),
        d_rgb_(9 * target->cos_thetas.size()) {
    set_num_residuals(static_cast<int>(3 * target->cos_thetas.size()));
    mutable_parameter_block_sizes()->push_back(kParams);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    if (jacobians && jacobians[0])
      evaluate_with_jacobian(parameters[0], residuals, jacobians[0]);
    else
      evaluate_residuals(parameters[0], residuals);
    return true;
  }

  static ceres::CostFunction* Create(const CurveTarget* target) {
    return new ModelCurveCost(target);
  }

 private:
  // The residuals alone: the channels in double.
  void evaluate_residuals(const double* p, double* residuals) const {
    using Prepared = decltype(fresnel::prepare_channel<Unit>(p, p));
    const Prepared q[3] = {fresnel::prepare_channel<Unit>(p, p + 3 * kPer),
                           fresnel::prepare_channel<Unit>(p + kPer, p + 3 * kPer),
                           fresnel::prepare_channel<Unit>(p + 2 * kPer, p + 3 * kPer)};
    const size_t n = target_->cos_thetas.size();
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        rgb_[i][c] = fresnel::channel_at<Unit>(target_->cos_thetas[i], q[c]);
    color::ciede2000_residuals_batch(target_->to_lab, target_->truth_lab, rgb_,
                                     std::span(residuals, 3 * n), d_rgb_);
  }

  // Flattened (FL_FLATTEN): the Dual lanes' loops are inlined.
  FL_FLATTEN void evaluate_with_jacobian(const double* p, double* residuals, double* jac) const {
    // Channel c's lanes: its own parameters, then the shared ones.
    ChannelDual pd[3][kChannelLanes];
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < kPer; ++k) pd[c][k] = ChannelDual::variable(p[c * kPer + k], k);
      for (int s = 0; s < kShared; ++s)
        pd[c][kPer + s] = ChannelDual::variable(p[3 * kPer + s], kPer + s);
    }
    // Each channel's angle-independent part once (fresnel::prepare_channel).
    using Prepared = decltype(fresnel::prepare_channel<Unit>(pd[0], pd[0]));
    const Prepared q[3] = {fresnel::prepare_channel<Unit>(pd[0], pd[0] + kPer),
                           fresnel::prepare_channel<Unit>(pd[1], pd[1] + kPer),
                           fresnel::prepare_channel<Unit>(pd[2], pd[2] + kPer)};
    const size_t n = target_->cos_thetas.size();
    for (size_t i = 0; i < n; ++i) {
      const ChannelDual cos_theta(target_->cos_thetas[i]);
      for (int c = 0; c < 3; ++c) {
        channels_[i][c] = fresnel::channel_at<Unit>(cos_theta, q[c]);
        rgb_[i][c] = channels_[i][c].v;
      }
    }
    color::ciede2000_residuals_batch(target_->to_lab, target_->truth_lab, rgb_,
                                     std::span(residuals, 3 * n), d_rgb_);
    for (size_t i = 0; i < n; ++i)
      for (int q = 0; q < 3; ++q) {
        const std::array<double, 3> d{d_rgb_[(3 * q) * n + i], d_rgb_[(3 * q + 1) * n + i],
                                      d_rgb_[(3 * q + 2) * n + i]};
        chain_rule(d, channels_[i], jac + (3 * i + q) * kParams);
      }
  }

  // One Jacobian row: d residual / d RGB times d RGB / d parameters.
  static void chain_rule(const std::array<double, 3>& d_rgb, const std::array<ChannelDual, 3>& ch,
                         double* row) {
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < kPer; ++k) row[c * kPer + k] = d_rgb[c] * ch[c].d[k];
    for (int s = 0; s < kShared; ++s)
      row[3 * kPer + s] = d_rgb[0] * ch[0].d[kPer + s] + d_rgb[1] * ch[1].d[kPer + s] +
                          d_rgb[2] * ch[2].d[kPer + s];
  }

  const CurveTarget* target_;
  // Per-angle scratch of evaluate_at (a cost function serves one single-threaded solve).
  mutable std::vector<color::Rgb> rgb_;
  mutable std::vector<std::array<ChannelDual, 3>> channels_;
  mutable std::vector<double> d_rgb_;
};

ceres::CostFunction* create_cost(Model m, const CurveTarget* target) {
  ceres::CostFunction* cost = nullptr;
  fresnel::visit_model(m,
                       [&](auto unit) { cost = ModelCurveCost<decltype(unit)>::Create(target); });
  return cost;
}

// The flat indices of the model's extinction parameters (ParamKind::Extinction).
std::vector<int> extinction_indices(Model m) {
  const auto& spec = fresnel::model_spec(m);
  std::vector<int> out;
  for (int c = 0; c < 3; ++c)
    for (int j = 0; j < spec.per_channel(); ++j)
      if (spec.channel_params[j].kind == fresnel::ParamKind::Extinction)
        out.push_back(c * spec.per_channel() + j);
  for (size_t j = 0; j < spec.shared_params.size(); ++j)
    if (spec.shared_params[j].kind == fresnel::ParamKind::Extinction)
      out.push_back(3 * spec.per_channel() + int(j));
  return out;
}

// A cost function that keeps the last point it was asked for, with its residuals and (once asked
// for) its Jacobian. With bounds, Ceres asks for a point more than once: the step's cost, the
// projected line search's trial with its gradient, then the accepted point's Jacobian. Each point is
// computed once; the answers are the same bits.
class LastPointCost : public ceres::CostFunction {
 public:
  explicit LastPointCost(ceres::CostFunction* cost) : cost_(cost) {
    *mutable_parameter_block_sizes() = cost->parameter_block_sizes();
    set_num_residuals(cost->num_residuals());
    const size_t params = static_cast<size_t>(cost->parameter_block_sizes()[0]);
    residuals_.resize(static_cast<size_t>(num_residuals()));
    jacobian_.resize(residuals_.size() * params);
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const bool want_jacobian = jacobians && jacobians[0];
    const size_t params = static_cast<size_t>(parameter_block_sizes()[0]);
    if (p_.empty() || !std::equal(p_.begin(), p_.end(), parameters[0])) {
      p_.assign(parameters[0], parameters[0] + params);
      double* jacobian = jacobian_.data();
      valid_ = cost_->Evaluate(parameters, residuals_.data(), want_jacobian ? &jacobian : nullptr);
      have_jacobian_ = want_jacobian;
    } else if (want_jacobian && !have_jacobian_ && valid_) {
      double* jacobian = jacobian_.data();
      valid_ = cost_->Evaluate(parameters, residuals_.data(), &jacobian);
      have_jacobian_ = true;
    }
    if (!valid_) return false;
    std::copy(residuals_.begin(), residuals_.end(), residuals);
    if (want_jacobian) std::copy(jacobian_.begin(), jacobian_.end(), jacobians[0]);
    return true;
  }

 private:
  std::unique_ptr<ceres::CostFunction> cost_;
  // The last point and what was computed there (a cost function serves one single-threaded solve).
  mutable std::vector<double> p_, residuals_, jacobian_;
  mutable bool valid_ = false, have_jacobian_ = false;
};

// One bounded solve of `cost` (owned by the problem from here) from `params`.
FitResult solve_cost(Model m, ceres::CostFunction* cost, std::vector<double> params,
                     const FitOptions& options) {
  const auto bounds = fresnel::model_spec(m).bounds();
  for (size_t i = 0; i < params.size(); ++i) {
    // Strictly inside the bounds: some kernels have kinks exactly at the ends (g = 0, F0 = 0).
    const double margin = 1e-9 * (bounds[i].hi - bounds[i].lo);
    params[i] = std::clamp(params[i], bounds[i].lo + margin, bounds[i].hi - margin);
  }
  const auto held = options.lossless ? extinction_indices(m) : std::vector<int>{};
  for (int i : held) params[i] = 0.0;
  ceres::Problem problem;
  problem.AddResidualBlock(new LastPointCost(cost), nullptr, params.data());
  if (!held.empty())
    problem.SetManifold(params.data(),
                        new ceres::SubsetManifold(static_cast<int>(params.size()), held));
  for (size_t i = 0; i < params.size(); ++i) {
    problem.SetParameterLowerBound(params.data(), static_cast<int>(i), bounds[i].lo);
    problem.SetParameterUpperBound(params.data(), static_cast<int>(i), bounds[i].hi);
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = options.max_iterations;
  so.function_tolerance = options.function_tolerance;
  so.gradient_tolerance = 1e-12;
  so.parameter_tolerance = 1e-10;
  so.logging_type = ceres::SILENT;
  so.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  FitResult r;
  r.parameters = params;
  r.cost = summary.final_cost;
  r.initial_cost = summary.initial_cost;
  r.iterations = static_cast<int>(summary.iterations.size()) - 1;
  r.termination = ceres::TerminationTypeToString(summary.termination_type);
  r.usable = summary.IsSolutionUsable() && std::isfinite(summary.final_cost);
  r.iteration_limit = summary.termination_type == ceres::NO_CONVERGENCE;
  return r;
}

FitResult solve_once(Model m, const CurveTarget& target, std::vector<double> params,
                     const FitOptions& options) {
  return solve_cost(m, create_cost(m, &target), std::move(params), options);
}

// ½ Σ ΔE2000² between a ColourTarget's truth and its colours: the residuals and their derivatives
// over RGB from one batch (color::ciede2000_residuals_batch), the colours' derivatives over the
// parameters by central differences (ColourTarget's contract), joined by the chain rule.
class ColourCost : public ceres::CostFunction {
 public:
  ColourCost(const ColourTarget* target, int params) : t_(target), n_(target->truth_lab.size()) {
    mutable_parameter_block_sizes()->push_back(params);
    set_num_residuals(static_cast<int>(3 * n_));
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int np = parameter_block_sizes()[0];
    std::vector<double> p(parameters[0], parameters[0] + np);
    std::vector<color::Rgb> rgb(n_), up(n_), down(n_);
    if (!t_->colours(p.data(), rgb.data())) return false;
    std::vector<double> d_rgb(9 * n_);
    color::ciede2000_residuals_batch(t_->to_lab, t_->truth_lab, rgb, std::span(residuals, 3 * n_),
                                     d_rgb);
    if (!jacobians || !jacobians[0]) return true;
    for (int j = 0; j < np; ++j) {
      // Step of 1e-6 relative (at least 1e-6): central differences' error is O(h²).
      const double h = 1e-6 * std::max(1.0, std::abs(p[j])), pj = p[j];
      p[j] = pj + h;
      if (!t_->colours(p.data(), up.data())) return false;
      p[j] = pj - h;
      if (!t_->colours(p.data(), down.data())) return false;
      p[j] = pj;
      for (size_t i = 0; i < n_; ++i)
        for (int q = 0; q < 3; ++q) {
          double d = 0;
          for (int c = 0; c < 3; ++c)
            d += d_rgb[(3 * q + c) * n_ + i] * (up[i][c] - down[i][c]) / (2 * h);
          jacobians[0][(3 * i + q) * np + j] = d;
        }
    }
    return true;
  }

 private:
  const ColourTarget* t_;
  size_t n_;
};

// ½ Σ ΔE2000² of a ColourTarget at `params` (infinity where it fails or is not finite).
double colour_cost(const ColourTarget& t, const std::vector<double>& params) {
  const size_t n = t.truth_lab.size();
  std::vector<color::Rgb> rgb(n);
  if (!t.colours(params.data(), rgb.data())) return std::numeric_limits<double>::infinity();
  std::vector<double> r(3 * n), d_rgb(9 * n);
  color::ciede2000_residuals_batch(t.to_lab, t.truth_lab, rgb, r, d_rgb);
  double cost = 0;
  for (double x : r) cost += 0.5 * x * x;
  return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
}

// ½ Σ ΔE2000² at `params`, from the residuals the solves minimize (ciede2000_residuals_batch).
double start_cost(Model m, const CurveTarget& target, const std::vector<double>& params) {
  const auto& spec = fresnel::model_spec(m);
  const size_t n = target.cos_thetas.size();
  std::vector<color::Rgb> rgb(n);
  for (size_t i = 0; i < n; ++i) rgb[i] = spec.evaluate(target.cos_thetas[i], params.data(), false);
  std::vector<double> residuals(3 * n), d_rgb(9 * n);
  color::ciede2000_residuals_batch(target.to_lab, target.truth_lab, rgb, residuals, d_rgb);
  double cost = 0;
  for (size_t i = 0; i < n; ++i) {
    const double* r = &residuals[3 * i];
    cost += 0.5 * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  }
  return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
}

// Parameters within a millionth of their box's width of a bound that the domain does not share,
// and held there by the data: moved 1% of the width inward, the RMS ΔE2000 rises by more than
// kPinnedRms. A parameter that does next to nothing where it ended (Lazányi's α once a ≈ 0)
// drifts to a bound without being pinned by it.
constexpr double kPinnedRms = 1e-4;  // a fifth of the tables' last printed digit (3 decimals)
std::vector<std::string> pinned_parameters(Model m, const CurveTarget& target,
                                           const std::vector<double>& p) {
  const auto& spec = fresnel::model_spec(m);
  const auto box = spec.bounds(), domain = spec.domain();
  const auto names = spec.param_names();
  const size_t n = target.cos_thetas.size();
  const double rms = rms_from_cost(start_cost(m, target, p), n);
  std::vector<std::string> out;
  for (size_t i = 0; i < p.size(); ++i) {
    const double width = box[i].hi - box[i].lo, tol = 1e-6 * width;
    const bool low = box[i].lo > domain[i].lo && p[i] <= box[i].lo + tol;
    const bool high = box[i].hi < domain[i].hi && p[i] >= box[i].hi - tol;
    if (!low && !high) continue;
    auto inside = p;
    inside[i] += (low ? 0.01 : -0.01) * width;
    if (rms_from_cost(start_cost(m, target, inside), n) > rms + kPinnedRms) out.push_back(names[i]);
  }
  return out;
}
}  // namespace

namespace {

// Ranks the starts by cost(start) (cheap), solves from the best few with solve(start) and keeps the
// lowest final cost; never worse than the best start.
template <class Cost, class Solve>
FitResult best_of_starts(Model m, std::vector<std::vector<double>> starts,
                         const FitOptions& options, Cost cost, Solve solve) {
  std::vector<std::pair<double, size_t>> ranked;
  const auto held = options.lossless ? extinction_indices(m) : std::vector<int>{};
  for (size_t i = 0; i < starts.size(); ++i) {
    if (static_cast<int>(starts[i].size()) != fresnel::model_spec(m).param_count())
      throw std::invalid_argument("fit_model: wrong parameter count");
    for (int h : held) starts[i][h] = 0.0;
    ranked.emplace_back(cost(starts[i]), i);
  }
  std::stable_sort(ranked.begin(), ranked.end());
  if (static_cast<int>(ranked.size()) > options.max_solves) ranked.resize(options.max_solves);
  FitResult best;
  bool have = false;
  for (const auto& [cost0, index] : ranked) {
    FitResult r = solve(starts[index]);
    if (r.usable && (!have || r.cost < best.cost)) {
      best = std::move(r);
      have = true;
    }
  }
  // Worse than the best start beyond rounding between the two cost evaluations (1e-9 relative,
  // and 1e-12 absolute: an RMS ΔE2000 near 1e-7 over 91 angles), e.g. a start outside the fit box,
  // or no usable solve: the start itself is returned.
  if (!have || best.cost > ranked.front().first * (1.0 + 1e-9) + 1e-12) {
    best.parameters = starts[ranked.front().second];
    best.cost = best.initial_cost = ranked.front().first;
    best.iterations = 0;
    best.termination = have ? "START_KEPT" : "NO_USABLE_SOLUTION";
    best.usable = have;
    best.kept_start = have;
    best.iteration_limit = false;
  }
  best.starts = static_cast<int>(ranked.size());
  return best;
}

}  // namespace

FitResult fit_model(Model m, const CurveTarget& target, std::vector<std::vector<double>> starts,
                    const FitOptions& options) {
  FitResult best = best_of_starts(
      m, std::move(starts), options,
      [&](const std::vector<double>& p) { return start_cost(m, target, p); },
      [&](const std::vector<double>& p) { return solve_once(m, target, p, options); });
  best.at_bound = pinned_parameters(m, target, best.parameters);
  return best;
}

FitResult fit_model_colours(Model m, const ColourTarget& target,
                            std::vector<std::vector<double>> starts, const FitOptions& options) {
  const int n = fresnel::model_spec(m).param_count();
  return best_of_starts(
      m, std::move(starts), options,
      [&](const std::vector<double>& p) { return colour_cost(target, p); },
      [&](const std::vector<double>& p) {
        return solve_cost(m, new ColourCost(&target, n), p, options);
      });
}

std::string fit_flags(const FitResult& r) {
  std::string out;
  auto add = [&](const std::string& f) { out += (out.empty() ? "" : " ") + f; };
  for (const auto& name : r.at_bound) add("at_bound:" + name);
  if (r.iteration_limit) add("iteration_limit");
  if (r.kept_start) add("kept_start");
  if (!r.usable) add("no_usable_solution");
  return out;
}

double rms_from_cost(double cost, size_t angles) {
  return std::sqrt(2.0 * cost / static_cast<double>(angles));
}

GradientCheck check_model_gradients(Model m, const CurveTarget& target,
                                    const std::vector<double>& params) {
  std::unique_ptr<ceres::CostFunction> cost(create_cost(m, &target));
  ceres::NumericDiffOptions nd;
  // The checker differentiates with Ridders' extrapolation, whose default first step (1 % of the
  // parameter) leaves the models' domains near their edges (g = 0.99 + 1 % > 1 breaks
  // Gulbrandsen's mapping); 1e-5 stays inside while extrapolation keeps the accuracy.
  nd.ridders_relative_initial_step_size = 1e-5;
  const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
  ceres::GradientChecker checker(cost.get(), no_manifolds, nd);
  ceres::GradientChecker::ProbeResults results;
  const double* blocks[] = {params.data()};
  GradientCheck out;
  checker.Probe(blocks, 1.0, &results);
  out.report = results.error_log;
  if (!results.return_value) return out;
  // Ceres' own relative error is meaningless where both derivatives are ~0; this measure is
  // relative for large entries and absolute below 1.
  const auto& a = results.jacobians[0];
  const auto& n = results.numeric_jacobians[0];
  for (int r = 0; r < a.rows(); ++r)
    for (int c = 0; c < a.cols(); ++c) {
      const double e =
          std::abs(a(r, c) - n(r, c)) / std::max({1.0, std::abs(a(r, c)), std::abs(n(r, c))});
      out.max_relative_error = std::max(out.max_relative_error, e);
    }
  out.ok = true;
  return out;
}

}  // namespace fl::fit
