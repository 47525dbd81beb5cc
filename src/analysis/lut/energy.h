#pragma once
// The tables of Kulla–Conty multiple-scattering energy compensation (Kulla & Conty 2017,
// "Revisiting Physically Based Shading at Imageworks"): the GGX lobe's directional albedo without
// Fresnel E(μ, α) = ∫ ρ(v, l) (n·l) dl at μ = n·v, and its hemispherical average
// E_avg(α) = 2∫₀¹ E(μ, α) μ dμ. With a model's F_avg (fresnel/average.h) an engine adds
// f_ms = (1 − E(μ_o))(1 − E(μ_i)) / (π (1 − E_avg)) scaled by
// F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)).
#include <vector>

#include "analysis/lut/lut.h"

namespace fl::analysis {

// Panels of 20 Gauss–Legendre nodes for E_avg's integral over μ
// (fresnel::hemispherical_average_of): E is smooth in μ: 4 panels agree with 16 to 1.4e-6 at every
// roughness of the 64² grid, far below the lobe samples' 2.5e-4.
inline constexpr int kEnergyAveragePanels = 4;

struct EnergyTable {
  LutGrid grid;               // dfg_grid: uv = (n·v, perceptual roughness)
  std::vector<double> e;      // E(n·v_i, α_j) per cell, grid.index(i, j)
  std::vector<double> e_avg;  // E_avg(α_j) per roughness
};

// E(μ, α) by the lobe samples of the DFG table (its n_D moment).
double directional_albedo(double nov, double alpha, const std::vector<brdf::DiskPoint>& points);
// E_avg(α) by Gauss–Legendre over μ of directional_albedo.
double average_albedo(double alpha, const std::vector<brdf::DiskPoint>& points);

// Both over `grid`, rows of roughness in parallel (results do not depend on threads).
EnergyTable energy_table(const LutGrid& grid, const LutOptions& options = {});

}  // namespace fl::analysis
