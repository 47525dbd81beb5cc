#pragma once
// The bounded solve every fit runs (fit.cpp's curve fits, colour_fit.cpp's colour fits): the starts
// ranked by their cost, the best few solved by Ceres within the model's fit box.
#include <functional>
#include <vector>

#include "fit/fit.h"

namespace ceres {
class CostFunction;
}

namespace fl::fit {

// One bounded solve of `cost` (owned by the solve from here) from `params`: Ceres' trust region
// within the model's fit box, the extinction parameters held at 0 for a lossless material.
FitResult solve_cost(fresnel::Model m, ceres::CostFunction* cost, std::vector<double> params,
                     const FitOptions& options);

using StartCost = std::function<double(const std::vector<double>& params)>;
using StartSolve = std::function<FitResult(const std::vector<double>& params)>;
// Ranks the starts by cost(start) (cheap), solves from the best options.max_solves with
// solve(start) and keeps the lowest final cost; never worse than the best start (kept_start).
FitResult best_of_starts(fresnel::Model m, std::vector<std::vector<double>> starts,
                         const FitOptions& options, const StartCost& cost, const StartSolve& solve);

}  // namespace fl::fit
