#pragma once
// The scene's options as `plan` weighs them (analysis/plan/plan.h): worst and median rendered
// ΔE2000 against GPU instructions per draw, the Pareto front joined, the chosen option marked, the
// budget dashed. A Drawing (draw.h) written as PNG, SVG or PDF by the file name's extension.
#include "analysis/plan/plan.h"
#include "draw/drawing.h"

namespace fl::draw {

// Options with an unmeasured instruction count have no place on the cost axis and are left out;
// errors above the axis (4 × the budget, or the largest error when smaller) sit on its top edge.
Drawing plan_plot(const analysis::Plan& plan);

}  // namespace fl::draw
