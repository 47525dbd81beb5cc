#pragma once
// Parameters fitted to the rendered result rather than to the curve: what an engine computes from
// the lookup tables (or from the model at n·v where no table holds it) under image-based and area
// lights, against the brute-force spectral lobe integrals (rendered.h), over every shading point.
#include <vector>

#include "analysis/lut/rendered.h"
#include "fit/fit.h"

namespace fl::analysis {

// The lightings a rendered fit matches, one parameter set for both (a material ships one).
inline constexpr std::array<Lighting, 2> kRenderedFitLightings{Lighting::Ibl, Lighting::Area};

// The rendered fits' stopping rule. Their costs have long flat valleys (several parameters trading
// against one another over 30 points), along which a solve stopped at the curve fits' rule (1e-10,
// 100 iterations) ends wherever the truth's last digits send it; run to a step gain of 1e-12 and
// up to 1000 iterations they reach the optimum (fits still at the limit are flagged
// iteration_limit).
inline constexpr double kRenderedFitTolerance = 1e-12;
inline constexpr int kRenderedFitMaxIterations = 1000;

// Minimizes ½ Σ ΔE2000² over kRenderedFitLightings × `points` (fit::fit_model_colours) between
// `truth` (lobe_truth at the points) and engine_shading, from `starts` (the derived and
// curve-fitted sets), within the model's fit box; each solve stops once a step lowers the cost by
// less than `function_tolerance` of it (fit::FitOptions), or after kRenderedFitMaxIterations.
fit::FitResult fit_rendered(const Context& ctx, const std::vector<color::Rgb>& truth,
                            fresnel::Model m, const std::vector<ShadingPoint>& points,
                            std::vector<std::vector<double>> starts, bool lossless,
                            double function_tolerance = kRenderedFitTolerance);

}  // namespace fl::analysis
