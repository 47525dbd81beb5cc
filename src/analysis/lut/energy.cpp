#include "analysis/lut/energy.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "fresnel/average.h"
#include "fresnel/exact.h"
#include "util/errors.h"
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

double dielectric_slice_f0(int k, int slices) {
  const double t = static_cast<double>(k) / (slices - 1);
  return kDielectricMaxF0 * (t * t) * (t * t);
}

double eta_from_f0(double f0) {
  const double r = std::sqrt(f0);
  return (1.0 + r) / (1.0 - r);
}

std::vector<double> dielectric_albedos(double nov, double alpha, const std::vector<double>& etas,
                                       const std::vector<brdf::DiskPoint>& points) {
  std::vector<double> sum(etas.size(), 0.0);
  for_each_lobe_sample(nov, alpha, points, [&](const LobeSample& s) {
    for (size_t m = 0; m < etas.size(); ++m)
      sum[m] += fresnel::fresnel_dielectric(s.voh, etas[m]) * s.weight;
  });
  for (double& x : sum) x /= static_cast<double>(points.size());
  return sum;
}

double critical_cosine(double eta) {
  return eta < 1.0 ? std::sqrt(1.0 - eta * eta) : 0.0;
}

std::vector<double> dielectric_average_albedos(double alpha, const std::vector<double>& etas,
                                               const std::vector<brdf::DiskPoint>& points) {
  std::vector<double> avg(etas.size(), 0.0), outside;
  for (const double eta : etas)
    if (eta >= 1.0) outside.push_back(eta);
  // η ≥ 1: smooth in μ, every index on the same nodes (the lobe samples shared).
  std::vector<double> sum_out(outside.size(), 0.0);
  for (const auto& node : fresnel::hemispherical_average_nodes(kEnergyAveragePanels)) {
    const auto e = dielectric_albedos(node.mu, alpha, outside, points);
    for (size_t m = 0; m < outside.size(); ++m) sum_out[m] += node.weight * e[m];
  }
  // η < 1: half the panels on either side of the critical cosine, where E_F has F's edge at α → 0.
  for (size_t m = 0, out = 0; m < etas.size(); ++m) {
    if (etas[m] >= 1.0) {
      avg[m] = sum_out[out++];
      continue;
    }
    const double mu_c = critical_cosine(etas[m]);
    for (const auto& [lo, hi] : {std::pair{0.0, mu_c}, std::pair{mu_c, 1.0}})
      for (const auto& node :
           fresnel::hemispherical_average_nodes(kEnergyAveragePanels / 2, lo, hi))
        avg[m] += node.weight * dielectric_albedos(node.mu, alpha, {etas[m]}, points)[0];
  }
  return avg;
}

namespace {

// The slices' indices: η_k for k < K, then 1/η_k.
std::vector<double> slice_etas(const std::vector<DielectricSlice>& slices) {
  std::vector<double> etas;
  for (const auto& s : slices) etas.push_back(s.eta);
  for (const auto& s : slices) etas.push_back(1.0 / s.eta);
  return etas;
}

// Row j of every slice: E_F at each n·v of the grid and E_F,avg, outside and inside.
void fill_dielectric_row(DielectricEnergyTable& t, int j,
                         const std::vector<brdf::DiskPoint>& points) {
  const auto& g = t.grid;
  const auto etas = slice_etas(t.slices);
  const size_t k_count = t.slices.size();
  for (int i = 0; i < g.size; ++i) {
    const auto e = dielectric_albedos(g.nov[i], g.alpha[j], etas, points);
    for (size_t k = 0; k < k_count; ++k) {
      t.slices[k].e_out[g.index(i, j)] = e[k];
      t.slices[k].e_in[g.index(i, j)] = e[k_count + k];
    }
  }
  const auto avg = dielectric_average_albedos(g.alpha[j], etas, points);
  for (size_t k = 0; k < k_count; ++k) {
    t.slices[k].e_avg_out[j] = avg[k];
    t.slices[k].e_avg_in[j] = avg[k_count + k];
  }
}

}  // namespace

DielectricEnergyTable dielectric_energy_table(const LutGrid& grid, int slices,
                                              const LutOptions& options) {
  if (slices < 2) throw InputError(fmt::format("{} dielectric slices: at least 2", slices));
  if (options.samples < 1)
    throw std::invalid_argument("dielectric_energy_table: samples must be positive");
  const auto points = lobe_disk_points(options.samples);
  const size_t cells = static_cast<size_t>(grid.size) * grid.size;
  DielectricEnergyTable t{grid, {}};
  for (int k = 0; k < slices; ++k) {
    const double f0 = dielectric_slice_f0(k, slices);
    t.slices.push_back({f0, eta_from_f0(f0), std::vector<double>(cells), std::vector<double>(cells),
                        std::vector<double>(grid.size), std::vector<double>(grid.size)});
  }
  ProgressCounter done(options.progress, grid.size);
  parallel_for(
      grid.size,
      [&](size_t j) {
        fill_dielectric_row(t, static_cast<int>(j), points);
        done.add(1);
      },
      options.threads);
  return t;
}

}  // namespace fl::analysis
