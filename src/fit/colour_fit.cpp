#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "color/ciede2000_batch.h"
#include "fit/fit.h"
#include "fit/solve.h"
#include "fresnel/registry.h"

namespace fl::fit {
namespace {

using fresnel::Model;

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

}  // namespace

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

}  // namespace fl::fit
