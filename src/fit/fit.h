#pragma once
// Numerical fits (Ceres). Ceres stays inside this module: callers see FitResult and plain data.
#include <string>
#include <vector>

#include "color/lab.h"
#include "fresnel/model_set.h"

namespace fl::fit {

// What every fit reports.
struct FitResult {
  std::vector<double> parameters;
  double cost = 0;          // Ceres' final cost, ½ Σ residual²
  double initial_cost = 0;  // at the start that won
  int iterations = 0;       // of the winning start
  std::string termination;  // CONVERGENCE, NO_CONVERGENCE, ...
  bool usable = false;      // the solver ended with a usable solution
  int starts = 1;           // how many starts were tried
};

// A ground-truth curve to fit; the cost is ½ Σ ΔE2000² over its angles.
struct CurveTarget {
  std::vector<double> cos_thetas;
  std::vector<color::Lab> truth_lab;
  color::LabConverter to_lab;
};

struct FitOptions {
  int max_iterations = 100;
  int max_solves = 2;  // starts ranked by their initial cost; only the best few are solved
};

// Fits the model's parameters to minimize the RMS ΔE2000 over the target's angles, within the
// model's bounds. The starts are ranked by cost, the best `max_solves` are solved, the lowest
// final cost wins. Starts are clamped into the bounds.
FitResult fit_model(fresnel::Model model, const CurveTarget& target, const std::vector<std::vector<double>>& starts,
                    const FitOptions& options = {});

// The RMS ΔE2000 a fit's cost stands for over N angles: sqrt(2·cost / N).
double rms_from_cost(double cost, size_t angles);

// ceres::GradientChecker on the model's cost function at `params`: the largest difference between
// the automatic and finite-difference Jacobians, relative for entries above 1 and absolute below.
// ok is false when the cost function could not be evaluated.
struct GradientCheck {
  bool ok = false;
  double max_relative_error = 0;
  std::string report;
};
GradientCheck check_model_gradients(fresnel::Model model, const CurveTarget& target, const std::vector<double>& params);

}  // namespace fl::fit
