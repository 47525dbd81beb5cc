#include "analysis/lut/rendered_fit.h"

namespace fl::analysis {

fit::FitResult fit_rendered(const Context& ctx, const std::vector<color::Rgb>& truth,
                            fresnel::Model m, const std::vector<ShadingPoint>& points,
                            std::vector<std::vector<double>> starts, bool lossless,
                            double function_tolerance) {
  fit::ColourTarget target;
  target.to_lab = {ctx.space().rgb_to_xyz, ctx.space().white};
  for (size_t l = 0; l < kRenderedFitLightings.size(); ++l)
    for (const auto& t : truth) target.truth_lab.push_back(target.to_lab(t));
  const size_t param_count = static_cast<size_t>(fresnel::model_spec(m).param_count());
  target.colours = [&](const double* p, color::Rgb* out) {
    const std::vector<double> params(p, p + param_count);
    for (const Lighting l : kRenderedFitLightings) {
      engine_shading(m, params, l, points, out);
      out += points.size();
    }
    return true;
  };
  fit::FitOptions options;
  options.lossless = lossless;
  options.max_solves = 1;  // from the better of the two starts
  options.function_tolerance = function_tolerance;
  options.max_iterations = kRenderedFitMaxIterations;
  return fit::fit_model_colours(m, target, std::move(starts), options);
}

}  // namespace fl::analysis
