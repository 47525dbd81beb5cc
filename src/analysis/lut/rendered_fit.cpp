#include "analysis/lut/rendered_fit.h"

#include "color/ciede2000_batch.h"

namespace fl::analysis {

fit::FitResult fit_rendered(const Context& ctx, const std::vector<color::Rgb>& truth,
                            fresnel::Model m, const std::vector<ShadingPoint>& points,
                            std::vector<std::vector<double>> starts, bool lossless) {
  const color::LabConverter to_lab{ctx.space().rgb_to_xyz, ctx.space().white};
  std::vector<color::Lab> truth_lab;
  for (size_t l = 0; l < kRenderedFitLightings.size(); ++l)
    for (const auto& t : truth) truth_lab.push_back(to_lab(t));
  const size_t n = truth_lab.size();
  const size_t param_count = static_cast<size_t>(fresnel::model_spec(m).param_count());
  const fit::ResidualFunction residuals = [&](const double* p, double* r) {
    const std::vector<double> params(p, p + param_count);
    std::vector<color::Rgb> rgb;
    rgb.reserve(n);
    for (const Lighting l : kRenderedFitLightings)
      for (const auto& point : points) rgb.push_back(engine_shading(m, params, l, point));
    std::vector<double> d_rgb(9 * n);
    color::ciede2000_residuals_batch(to_lab, truth_lab, rgb, std::span<double>(r, 3 * n), d_rgb);
    return true;
  };
  fit::FitOptions options;
  options.lossless = lossless;
  options.max_solves = 1;  // from the better of the two starts
  return fit::fit_model_residuals(m, static_cast<int>(3 * n), residuals, std::move(starts),
                                  options);
}

}  // namespace fl::analysis
