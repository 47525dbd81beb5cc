#pragma once
// LTC tables (Heitz, Dupuy, Hill & Neubelt 2016): every cell of ltc_grid fitted with a linearly
// transformed cosine (ltc_fit.h), the texture's entries, and the horizon-clipped sphere form
// factor the area-light shader reads beside them.
#include <array>
#include <vector>

#include "analysis/ltc/ltc_fit.h"
#include "analysis/lut/lut.h"

namespace fl::analysis {

// Snyder 1996, "Area Light Sources for Real-Time Graphics" (as tabulated by Heitz & Hill's
// ltc_code, genSphereTab): the cosine-weighted solid angle of a sphere clipped to the horizon,
// divided by π·len, for a sphere whose vector form factor has z-component `z` of its unit direction
// and length `len` = sin²σ (σ the sphere's angular radius).
double horizon_clipped_sphere_form_factor(double z, double len);
// Texel (i, j) at z = 2i/(N − 1) − 1, len = j/(N − 1); stored j-major.
std::vector<double> sphere_form_factor_table(int size);

struct LtcCell {
  LtcParams params;
  LtcMatrix m, m_inv;
  // The texture's four entries of M⁻¹ normalized by M⁻¹₁₁ (row-major indices):
  // (M⁻¹₀₀, M⁻¹₂₀, M⁻¹₀₂, M⁻¹₂₂) / M⁻¹₁₁, i.e. ltc_code's (invM[0][0], invM[0][2], invM[2][0],
  // invM[2][2]) in glm's column-major indexing.
  std::array<double, 4> inv_packed{};
  fit::FitResult fit;
  double fit_error = 0;  // held-out relative L3 error of the cell's LTC (LtcCellFit::heldout_error)
  int rounds = 0;        // LtcCellFit::rounds
  bool kept_start = false;  // LtcCellFit::kept_start
};
// The texture's entries of one cell: (M⁻¹₀₀, M⁻¹₂₀, M⁻¹₀₂, M⁻¹₂₂) / M⁻¹₁₁ (LtcCell::inv_packed).
std::array<double, 4> ltc_texture_entries(const LtcMatrix& m_inv);
struct LtcTable {
  LutGrid grid;
  std::vector<GgxMoments> moments;
  std::vector<LtcCell> cells;
  std::vector<double> sphere_form_factor;  // sphere_form_factor_table(grid.size)
};

// fit_ltc_cell's near-equal choice, in the grazing row (i = N − 1, θ = 1.57) only. There the
// lobe changes fastest with θ and the L3 optimum is flattest: at roughness 1 the optimum steps by
// 0.14 in M⁻¹₂₂ from the cell at i = N − 2 (by 0.08 between i = N − 3 and N − 2), while the
// continuation (extrapolate_ltc_start) is within 0.5% of its held-out error. Elsewhere the fit
// is kept: a bilinear lookup between two near-optimal cells measured as good as or better than
// between cells moved towards their continuations (the choice in every row raised the cells' and
// the midpoints' mean held-out error by about 1%).
inline constexpr double kLtcGrazingNearEqualMargin = 0.01;

// One solve of a cell's problem from a start; the isotropic flag holds m13 and m31 (normal
// incidence).
using LtcCellFitter = LtcSolver;

// Fits every cell of ltc_grid(size) with fit_ltc_cell, in Heitz's fitLTC.cpp order: the
// normal-incidence column from rough to smooth, each cell starting from the rougher one; then every
// roughness row from normal to grazing, each cell starting from the previous ones (the
// extrapolation extrapolate_ltc_start first, then the previous cell), the grazing row with the
// near-equal choice (kLtcGrazingNearEqualMargin). Rows run in parallel; results do not depend on
// threads.
LtcTable fit_ltc_table(int size, const LutOptions& options = {},
                       const LtcCellFitter& fitter = fit_ltc_ceres,
                       int fit_sample_sqrt = kLtcDefaultSampleSqrt);

}  // namespace fl::analysis
