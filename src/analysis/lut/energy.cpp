#include "analysis/lut/energy.h"

#include "fresnel/average.h"
#include "util/parallel.h"

namespace fl::analysis {

double directional_albedo(double nov, double alpha, const std::vector<brdf::DiskPoint>& points) {
  return integrate_moments(nov, alpha, points)[fresnel::Term::One];
}

double average_albedo(double alpha, const std::vector<brdf::DiskPoint>& points) {
  const color::Rgb avg = fresnel::hemispherical_average_of(
      [&](double mu) {
        const double e = directional_albedo(mu, alpha, points);
        return color::Rgb{e, e, e};
      },
      kEnergyAveragePanels);
  return avg[0];
}

EnergyTable energy_table(const LutGrid& grid, const LutOptions& options) {
  if (options.samples < 1) throw std::invalid_argument("energy_table: samples must be positive");
  const auto points = lobe_disk_points(options.samples);
  EnergyTable t{grid, std::vector<double>(static_cast<size_t>(grid.size) * grid.size),
                std::vector<double>(grid.size)};
  ProgressCounter done(options.progress, grid.size);
  parallel_for(
      grid.size,
      [&](size_t j) {
        const double alpha = grid.alpha[j];
        for (int i = 0; i < grid.size; ++i)
          t.e[grid.index(i, static_cast<int>(j))] = directional_albedo(grid.nov[i], alpha, points);
        t.e_avg[j] = average_albedo(alpha, points);
        done.add(1);
      },
      options.threads);
  return t;
}

}  // namespace fl::analysis
