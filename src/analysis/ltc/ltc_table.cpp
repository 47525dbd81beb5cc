#include "analysis/ltc/ltc_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/errors.h"
#include "util/parallel.h"

namespace fl::analysis {
namespace {

void check_size(int size) {
  if (size < 2 || size > 4096)
    throw InputError(fmt::format("table size {} out of range (2 to 4096)", size));
}

// Fits cell (i, j) of an LTC grid from its starts (fit_ltc_cell); i = 0 (normal incidence) is
// isotropic.
LtcCell fit_table_cell(const LutGrid& g, const GgxMoments& mo, int i, int j,
                       const std::vector<LtcParams>& starts, const LtcCellFitter& fitter,
                       const LtcCellPoints& points) {
  const bool isotropic = i == 0;
  const brdf::Vec3 dir = isotropic ? brdf::Vec3{0, 0, 1} : mo.average_dir;
  const double near_equal_margin = i == g.size - 1 ? kLtcGrazingNearEqualMargin : 0.0;
  const auto r = fit_ltc_cell(g.nov[i], g.alpha[j], mo[fresnel::Term::One], dir, starts, isotropic,
                              fitter, points, near_equal_margin);
  LtcCell c;
  c.fit = r.fit;
  c.params = r.params;
  c.fit_error = r.heldout_error;
  c.rounds = r.rounds;
  c.kept_start = r.kept_start;
  c.m = ltc_matrix(ltc_frame_from_average_direction(dir), c.params);
  c.m_inv = inverse(c.m);
  c.inv_packed = ltc_texture_entries(c.m_inv);
  return c;
}

}  // namespace

std::array<double, 4> ltc_texture_entries(const LtcMatrix& m_inv) {
  const double s = 1.0 / m_inv(1, 1);
  return {m_inv(0, 0) * s, m_inv(2, 0) * s, m_inv(0, 2) * s, m_inv(2, 2) * s};
}

double horizon_clipped_sphere_form_factor(double z, double len) {
  z = std::clamp(z, -1.0, 1.0);
  len = std::clamp(len, 0.0, 1.0);
  if (len <= 0.0) return std::max(z, 0.0);
  const double sigma = std::asin(std::sqrt(len));  // angular radius of the sphere
  const double omega = std::acos(z);               // angle of its centre from the normal
  const double sin_s = std::sin(sigma), cos_s = std::cos(sigma), sin2_s = sin_s * sin_s;
  const double cos_w = std::cos(omega), sin_w = std::sin(omega);
  // Snyder 1996, eq. for the partially visible cap: γ = asin(cos σ / sin ω) and the terms G, H.
  auto terms = [&](double& g_term, double& h_term) {
    const double gamma = std::asin(std::clamp(cos_s / sin_w, -1.0, 1.0));
    const double cos_g = std::cos(gamma), sin_g = std::sin(gamma);
    g_term = -2.0 * sin_w * cos_s * cos_g + std::numbers::pi / 2.0 - gamma + sin_g * cos_g;
    h_term = cos_w * (cos_g * std::sqrt(std::max(0.0, sin2_s - cos_g * cos_g)) +
                      sin2_s * std::asin(std::clamp(cos_g / sin_s, -1.0, 1.0)));
  };
  double projected = 0.0;  // cosine-weighted solid angle of the visible part of the cap
  if (omega <= std::numbers::pi / 2.0 - sigma) {
    projected = std::numbers::pi * cos_w * sin2_s;
  } else if (omega < std::numbers::pi / 2.0) {
    double g_term = 0, h_term = 0;
    terms(g_term, h_term);
    projected = std::numbers::pi * cos_w * sin2_s + g_term - h_term;
  } else if (omega < std::numbers::pi / 2.0 + sigma) {
    double g_term = 0, h_term = 0;
    terms(g_term, h_term);
    projected = g_term + h_term;
  }
  return projected / (std::numbers::pi * len);
}

std::vector<double> sphere_form_factor_table(int size) {
  check_size(size);
  std::vector<double> out(static_cast<size_t>(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      out[static_cast<size_t>(j) * size + i] = horizon_clipped_sphere_form_factor(
          2.0 * i / (size - 1) - 1.0, static_cast<double>(j) / (size - 1));
  return out;
}

LtcTable fit_ltc_table(int size, const LutOptions& options, const LtcCellFitter& fitter,
                       int fit_sample_sqrt) {
  LtcTable t;
  t.grid = ltc_grid(size);
  const auto& g = t.grid;
  t.cells.resize(static_cast<size_t>(size) * size);
  const LtcCellPoints points = ltc_cell_points(fit_sample_sqrt);
  const auto fit_cell = [&](int i, int j, const std::vector<LtcParams>& starts) {
    t.cells[g.index(i, j)] =
        fit_table_cell(g, t.moments[g.index(i, j)], i, j, starts, fitter, points);
  };
  // Progress counts every cell twice: once for its moments, once for its fit.
  ProgressCounter done(options.progress, 2 * size * size);

  // Stage 1: moments and mean directions (the LTC magnitudes and frames), every cell independent.
  t.moments = moments_table(g, options, done).cells;
  // Stage 2: the normal-incidence column, rough to smooth (sequential warm starts).
  for (int j = size - 1; j >= 0; --j) {
    LtcParams start;
    if (j < size - 1) {
      const auto& rougher = t.cells[g.index(0, j + 1)].params;
      start = {rougher.m11, rougher.m22, 0.0, 0.0};
    }
    fit_cell(0, j, {start});
  }
  done.add(size);
  // Stage 3: each roughness row from normal to grazing (warm starts along the row); rows in
  // parallel.
  parallel_for(
      size,
      [&](size_t row) {
        const int j = static_cast<int>(row);
        fit_cell(1, j, {t.cells[g.index(0, j)].params});
        for (int i = 2; i < size; ++i) {
          const auto& prev = t.cells[g.index(i - 1, j)].params;
          fit_cell(i, j, {extrapolate_ltc_start(prev, t.cells[g.index(i - 2, j)].params), prev});
        }
        done.add(size - 1);
      },
      options.threads);
  t.sphere_form_factor = sphere_form_factor_table(size);
  return t;
}

}  // namespace fl::analysis
