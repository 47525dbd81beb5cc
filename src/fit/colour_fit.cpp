#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "color/ciede2000_batch.h"
#include "fit/fit.h"
#include "fit/solve.h"
#include "fresnel/registry.h"

namespace fl::fit {
namespace {

using fresnel::Model;

// ½ Σ ΔE2000² between a ColourTarget's truth and its colours: the residuals and their derivatives
// over RGB from one batch (color::ciede2000_residuals_batch), the colours' derivatives over the
// parameters by central differences (ColourTarget's contract), joined by the chain rule. Channel c
// reads only its own parameter block and the shared parameters, so parameter k of the three blocks
// is stepped in one pair of evaluations: each channel's difference is its own parameter's.
class ColourCost : public ceres::CostFunction {
 public:
  ColourCost(const ColourTarget* target, Model m)
      : t_(target), n_(target->truth_lab.size()), per_(fresnel::model_spec(m).per_channel()) {
    mutable_parameter_block_sizes()->push_back(fresnel::model_spec(m).param_count());
    set_num_residuals(static_cast<int>(3 * n_));
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int np = parameter_block_sizes()[0];
    std::vector<double> p(parameters[0], parameters[0] + np);
    std::vector<color::Rgb> rgb(n_);
    if (!t_->colours(p.data(), rgb.data())) return false;
    std::vector<double> d_rgb(9 * n_);
    color::ciede2000_residuals_batch(t_->to_lab, t_->truth_lab, rgb, std::span(residuals, 3 * n_),
                                     d_rgb);
    if (!jacobians || !jacobians[0]) return true;
    const Differences d{rgb, d_rgb, jacobians[0], np};
    for (int k = 0; k < per_; ++k) {
      const std::array<int, 3> blocks{k, per_ + k, 2 * per_ + k};
      if (!step_columns(p, blocks, d)) return false;
    }
    for (int s = 3 * per_; s < np; ++s)
      if (!step_columns(p, std::span(&s, 1), d)) return false;
    return true;
  }

 private:
  struct Differences {
    const std::vector<color::Rgb>& rgb;
    const std::vector<double>& d_rgb;
    double* jacobian;
    int np;
  };

  // The Jacobian's columns `cols` from one pair of evaluations with each of them stepped by ±h
  // (1e-6 relative, at least 1e-6: central differences' error is O(h²)). A column of a channel's
  // block takes that channel's difference; the others' are zero, as they would be were the column
  // stepped alone (rgb − rgb keeps the bits of up − down then).
  bool step_columns(std::vector<double>& p, std::span<const int> cols, const Differences& d) const {
    std::vector<color::Rgb> up(n_), down(n_);
    std::array<double, 3> h{}, pj{};
    for (size_t m = 0; m < cols.size(); ++m)
      pj[m] = p[cols[m]], h[m] = 1e-6 * std::max(1.0, std::abs(pj[m]));
    for (size_t m = 0; m < cols.size(); ++m) p[cols[m]] = pj[m] + h[m];
    if (!t_->colours(p.data(), up.data())) return false;
    for (size_t m = 0; m < cols.size(); ++m) p[cols[m]] = pj[m] - h[m];
    if (!t_->colours(p.data(), down.data())) return false;
    for (size_t m = 0; m < cols.size(); ++m) p[cols[m]] = pj[m];
    for (size_t m = 0; m < cols.size(); ++m) {
      const int j = cols[m];
      const int own = j < 3 * per_ ? j / per_ : -1;  // the channel whose block holds j, or shared
      for (size_t i = 0; i < n_; ++i)
        for (int q = 0; q < 3; ++q) {
          double v = 0;
          for (int c = 0; c < 3; ++c) {
            const double diff =
                own < 0 || c == own ? up[i][c] - down[i][c] : d.rgb[i][c] - d.rgb[i][c];
            v += d.d_rgb[(3 * q + c) * n_ + i] * diff / (2 * h[m]);
          }
          d.jacobian[(3 * i + q) * d.np + j] = v;
        }
    }
    return true;
  }

  const ColourTarget* t_;
  size_t n_;
  int per_;
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
  return best_of_starts(
      m, std::move(starts), options,
      [&](const std::vector<double>& p) { return colour_cost(target, p); },
      [&](const std::vector<double>& p) {
        return solve_cost(m, new ColourCost(&target, m), p, options);
      });
}

}  // namespace fl::fit
