#pragma once
// A cost function's last evaluation, returned again when Ceres asks at the same parameters.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

namespace fl::fit {

// Ceres' bounded trust-region step evaluates each accepted point up to three times (the projected
// line search's cost and gradient, the candidate's cost, then the Jacobian). A cost function keeps
// its last point's residuals and row-major Jacobian here and returns them for bit-identical
// parameters. Not for concurrent use: a solve runs single-threaded (num_threads = 1).
template <int kParams>
class KeptEvaluation {
 public:
  explicit KeptEvaluation(size_t residuals)
      : residuals_(residuals), jacobian_(residuals * kParams) {}

  // The residuals at p into `residuals` (compute_residuals(p, out) when p differs from the last
  // point), and, when `jacobian` is not null, the Jacobian (compute_jacobian(p, out), always after
  // compute_residuals at the same p).
  template <class Residuals, class Jacobian>
  void evaluate(const double* p, double* residuals, double* jacobian, Residuals compute_residuals,
                Jacobian compute_jacobian) {
    if (moved_to(p) || !have_residuals_) {
      compute_residuals(p, residuals_.data());
      have_residuals_ = true;
      have_jacobian_ = false;
    }
    std::copy(residuals_.begin(), residuals_.end(), residuals);
    if (!jacobian) return;
    if (!have_jacobian_) compute_jacobian(p, jacobian_.data());
    have_jacobian_ = true;
    std::copy(jacobian_.begin(), jacobian_.end(), jacobian);
  }

  // The same for a cost function that computes its residuals and Jacobian in one pass
  // (compute(p, residuals, jacobian)): both are computed at each new point, since Ceres asks for
  // the Jacobian at nearly every point whose residuals it asks for (the model fits of `reproduce`:
  // 6,016 Jacobians at 6,129 points).
  template <class Both>
  void evaluate_joint(const double* p, double* residuals, double* jacobian, Both compute) {
    if (moved_to(p) || !have_jacobian_) {
      compute(p, residuals_.data(), jacobian_.data());
      have_residuals_ = have_jacobian_ = true;
    }
    std::copy(residuals_.begin(), residuals_.end(), residuals);
    if (jacobian) std::copy(jacobian_.begin(), jacobian_.end(), jacobian);
  }

 private:
  // Whether p differs from the kept point (bit for bit); the kept point becomes p either way.
  bool moved_to(const double* p) {
    if (std::memcmp(p, at_, sizeof at_) == 0) return false;
    std::memcpy(at_, p, sizeof at_);
    return true;
  }

  double at_[kParams] = {};
  bool have_residuals_ = false, have_jacobian_ = false;
  std::vector<double> residuals_, jacobian_;
};

}  // namespace fl::fit
