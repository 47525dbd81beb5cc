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

// ----- dielectrics: the specular lobe WITH the exact dielectric Fresnel reflectance
// (fresnel::fresnel_dielectric, unpolarized), reflection only:
// E_F(μ, α, η) = ∫ F(v·h, η) ρ(v, l) (n·l) dl and E_F,avg(α, η) = 2∫₀¹ E_F(μ, α, η) μ dμ.
// η is the relative index of the side below the surface to the side of v (η_t/η_i). At α → 0,
// E_F(μ) → F(μ, η), so E_F,avg at roughness 0 is F_avg(η); at η = 1, E_F = 0; as η → ∞, F → 1 and
// E_F → E(μ, α).
//
// Slices: K slices uniform in t = (F0/kDielectricMaxF0)^¼, F0 = ((η − 1)/(η + 1))², from η = 1
// (t = 0) to η = 3 (t = 1, F0 = 0.25): F0_k = kDielectricMaxF0·(k/(K − 1))⁴. An engine interpolates
// linearly in t = √(2|η − 1|/(η + 1)) between the two slices around its η. Near η = 1 E_F changes
// fastest (at grazing v·h, F rises over a width in v·h that scales as F0^¼), so the slices crowd
// there: midway between two of 16 slices (n·v ≥ 0.2, α ≥ 0.1) linear interpolation in t errs by
// 1.9e-3 outside and 0.054 inside, in F0 by 0.061 and 0.42, in η by 0.0083 and 0.32.
// Each slice holds η_k (outside, η ≥ 1) and 1/η_k (inside a medium looking out: the same F0, with
// total internal reflection past the critical angle).
inline constexpr double kDielectricMaxF0 = 0.25;
inline constexpr int kDielectricSlices = 16;
// F0_k = kDielectricMaxF0·(k/(K − 1))⁴, and η = (1 + √F0)/(1 − √F0) ≥ 1.
double dielectric_slice_f0(int k, int slices);
double eta_from_f0(double f0);

// E_F(μ, α, η) for every η of `etas` on the lobe samples of one view (the samples shared).
std::vector<double> dielectric_albedos(double nov, double alpha, const std::vector<double>& etas,
                                       const std::vector<brdf::DiskPoint>& points);
// √(1 − η²) for η < 1: below this v·h, F = 1 (total internal reflection); 0 for η ≥ 1.
double critical_cosine(double eta);
// E_F,avg(α, η) for every η of `etas`, by Gauss–Legendre over μ (kEnergyAveragePanels; for η < 1,
// half of them on either side of the critical cosine).
std::vector<double> dielectric_average_albedos(double alpha, const std::vector<double>& etas,
                                               const std::vector<brdf::DiskPoint>& points);

struct DielectricSlice {
  double f0 = 0, eta = 1;                   // η ≥ 1 (outside); the inside is 1/η
  std::vector<double> e_out, e_in;          // E_F at η and at 1/η per cell, grid.index(i, j)
  std::vector<double> e_avg_out, e_avg_in;  // E_F,avg at η and at 1/η per roughness
};
struct DielectricEnergyTable {
  LutGrid grid;  // dfg_grid: uv = (n·v, perceptual roughness) within each slice
  std::vector<DielectricSlice> slices;
};
// Every slice over `grid` (slices ≥ 2), rows of roughness in parallel.
DielectricEnergyTable dielectric_energy_table(const LutGrid& grid, int slices,
                                              const LutOptions& options = {});

}  // namespace fl::analysis
