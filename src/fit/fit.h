#pragma once
// Numerical fits (Ceres). Ceres stays inside this module: callers see FitResult.
#include <string>
#include <vector>

namespace fl::fit {

// What every fit reports.
struct FitResult {
  std::vector<double> parameters;
  double cost = 0;         // Ceres' final cost (½ Σ residual²)
  double initial_cost = 0;
  int iterations = 0;
  std::string termination; // CONVERGENCE, NO_CONVERGENCE, ...
  bool usable = false;     // the solver finished with a usable solution
  int starts = 1;          // how many starts were tried
};

}  // namespace fl::fit
