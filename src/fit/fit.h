#pragma once
// Numerical fits (Ceres). Ceres stays inside this module: callers see FitResult and plain data.
#include <functional>
#include <string>
#include <vector>

#include "color/lab.h"
#include "fresnel/registered_models.h"

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
  bool kept_start = false;  // no solve ended below the best start's cost: the best start itself
  bool iteration_limit = false;  // the winning solve stopped at FitOptions::max_iterations
  std::vector<std::string>
      at_bound;  // parameters ending on a fit-box bound that is not the domain's
};

// The quality flags of a fit, space-separated (empty when there are none): "at_bound:eta_g"
// (a parameter pinned by its fit box, ParamSpec::fit, where the kernel's domain goes on),
// "iteration_limit", "kept_start" (no solve improved on the best start, which is returned),
// "no_usable_solution".
std::string fit_flags(const FitResult& r);

// A ground-truth curve to fit; the cost is ½ Σ ΔE2000² over its angles.
struct CurveTarget {
  std::vector<double> cos_thetas;
  std::vector<color::Lab> truth_lab;
  color::LabConverter to_lab;
};

struct FitOptions {
  int max_iterations = 100;
  int max_solves = 2;  // starts ranked by their initial cost; only the best few are solved
  // A solve stops once a step lowers the cost by less than this share of it (Ceres'
  // function_tolerance).
  double function_tolerance = 1e-10;
  // Extinction parameters (ParamKind::Extinction) held at 0: the material is lossless.
  bool lossless = false;
};

// Fits the model's parameters to minimize the RMS ΔE2000 over the target's angles, within the
// model's bounds. The starts are ranked by cost, the best `max_solves` are solved, the lowest
// final cost wins. Starts are clamped into the bounds. The result is never worse than the best
// start: when no solve ends below its cost, the start itself is returned (kept_start).
FitResult fit_model(fresnel::Model model, const CurveTarget& target,
                    std::vector<std::vector<double>> starts, const FitOptions& options = {});

// Colours that depend on a model's parameters (rendered shading, say) and the truth they should
// match: `colours(params, out)` fills truth_lab.size() RGB values and returns true, or false where
// it cannot be evaluated. Differentiated by central differences, so it must be smooth in the
// parameters and pure, and, as a model's channels do, channel c of every colour must read only
// channel c's parameter block and the shared parameters (model_spec.h's layout): parameter k of
// the three blocks is stepped in one pair of evaluations. The ΔE2000 residuals' derivatives over
// RGB are exact.
struct ColourTarget {
  std::vector<color::Lab> truth_lab;
  color::LabConverter to_lab;
  std::function<bool(const double* params, color::Rgb* out)> colours;
};
// fit_model for ½ Σ ΔE2000² between the target's truth and its colours, within the model's fit box
// (the same starts, ranking and never-worse-than-the-best-start rule; no at_bound check).
FitResult fit_model_colours(fresnel::Model model, const ColourTarget& target,
                            std::vector<std::vector<double>> starts,
                            const FitOptions& options = {});

// The largest k (over the grid) of a material whose fits hold κ at 0: below it k changes a
// reflectance by k²/(n − 1)² < 4e-6 relative at n = 1.5, nothing a colour difference can see.
inline constexpr double kLosslessMaxK = 1e-3;

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
GradientCheck check_model_gradients(fresnel::Model model, const CurveTarget& target,
                                    const std::vector<double>& params);

}  // namespace fl::fit
