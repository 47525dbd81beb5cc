#include "fit/fit.h"

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "color/ciede2000_batch.h"
#include "color/dual.h"
#include "fit/solve.h"
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

FitResult solve_once(Model m, const CurveTarget& target, std::vector<double> params,
                     const FitOptions& options) {
  return solve_cost(m, create_cost(m, &target), std::move(params), options);
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

FitResult fit_model(Model m, const CurveTarget& target, std::vector<std::vector<double>> starts,
                    const FitOptions& options) {
  FitResult best = best_of_starts(
      m, std::move(starts), options,
      [&](const std::vector<double>& p) { return start_cost(m, target, p); },
      [&](const std::vector<double>& p) { return solve_once(m, target, p, options); });
  best.at_bound = pinned_parameters(m, target, best.parameters);
  return best;
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
