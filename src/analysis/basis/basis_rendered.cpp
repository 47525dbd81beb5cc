#include "analysis/basis/basis_rendered.h"

#include <cmath>

#include "color/lab.h"

namespace fl::analysis {

// The truth is Σ_k w_k·curve(μ_k) (lobe_truth): a function's integral is the same sum.
RenderedSets rendered_sets(const std::vector<std::vector<std::vector<double>>>& sets_at_nodes,
                           std::vector<ShadingPoint> points) {
  RenderedSets out;
  out.points = std::move(points);
  for (const auto& set : sets_at_nodes) {
    std::vector<std::vector<double>> per_function;
    for (const auto& f : set) {
      std::vector<double> at_points;
      for (const auto& p : out.points) {
        double sum = 0;
        for (size_t k = 0; k < f.size(); ++k) sum += p.truth_weights[k] * f[k];
        at_points.push_back(sum);
      }
      per_function.push_back(std::move(at_points));
    }
    out.integrals.push_back(std::move(per_function));
  }
  return out;
}

double rendered_rms(const Context& ctx, const std::vector<color::Rgb>& lobe,
                    const std::vector<std::vector<double>>& integrals,
                    const std::array<std::vector<double>, 3>& coefficients) {
  double sum = 0;
  for (size_t p = 0; p < lobe.size(); ++p) {
    color::Rgb engine{};
    for (int c = 0; c < 3; ++c)
      for (size_t t = 0; t < integrals.size(); ++t)
        engine[c] += coefficients[c][t] * integrals[t][p];
    const double e = color::ciede2000(ctx.rgb_to_lab(lobe[p]), ctx.rgb_to_lab(engine));
    sum += e * e;
  }
  return std::sqrt(sum / double(lobe.size()));
}

}  // namespace fl::analysis
