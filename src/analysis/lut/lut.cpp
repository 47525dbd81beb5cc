#include "analysis/lut/lut.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "brdf/sheen.h"
#include "color/lab.h"
#include "fresnel/table_terms.h"
#include "util/codegen.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/quantile.h"

namespace fl::analysis {

namespace {

// Heitz's fitLTC.cpp caps θ_v below π/2 so the view vector never lies in the surface.
constexpr double kLtcMaxThetaRad = 1.57;

void check_size(int size) {
  if (size < 2 || size > 4096)
    throw InputError(fmt::format("table size {} out of range (2 to 4096)", size));
}
void check_samples(int samples) {
  if (samples < 1) throw InputError(fmt::format("sample count {} must be positive", samples));
}

double pow5(double x) {
  const double x2 = x * x;
  return x2 * x2 * x;
}

}  // namespace

double texel_coordinate(TexelPlacement placement, double x, int texels) {
  return placement == TexelPlacement::Endpoints ? x * (texels - 1) : x * texels - 0.5;
}

LutGrid dfg_grid(int size) {
  check_size(size);
  LutGrid g;
  g.size = size;
  for (int i = 0; i < size; ++i) {
    const double x = static_cast<double>(i) / (size - 1);
    g.nov.push_back(std::max(x, std::cos(kLtcMaxThetaRad)));
    g.perceptual_roughness.push_back(x);
    g.alpha.push_back(ltc_alpha_at(x));
  }
  g.placement = TexelPlacement::Endpoints;
  g.convention = fmt::format(
      "endpoints: nov = max(i/{0}, cos(1.57)), perceptual_roughness = j/{0}, alpha = "
      "max(perceptual_roughness^2, {1:g}); sample at uv = (nov, perceptual_roughness)*({0}/{2}) + "
      "0.5/{2}",
      size - 1, kLtcMinAlpha, size);
  return g;
}

LutGrid filament_dfg_grid(int size) {
  check_size(size);
  LutGrid g;
  g.size = size;
  for (int i = 0; i < size; ++i) {
    const double c = (i + 0.5) / size;
    g.nov.push_back(c);
    g.perceptual_roughness.push_back(c);
    g.alpha.push_back(c * c);
  }
  g.placement = TexelPlacement::Centres;
  g.convention = fmt::format(
      "texel centres: nov = (i + 0.5)/{0}, perceptual_roughness = (j + 0.5)/{0}, alpha = "
      "perceptual_roughness^2",
      size);
  return g;
}

double ltc_nov_at(double x) {
  if (x <= 0.0) return 1.0;
  return std::cos(std::min(kLtcMaxThetaRad, std::acos(std::max(-1.0, 1.0 - x * x))));
}

double ltc_alpha_at(double roughness) {
  return std::max(roughness * roughness, kLtcMinAlpha);
}

LutGrid ltc_grid(int size) {
  check_size(size);
  LutGrid g;
  g.size = size;
  for (int i = 0; i < size; ++i) {
    const double x = static_cast<double>(i) / (size - 1);
    g.nov.push_back(ltc_nov_at(x));
    g.perceptual_roughness.push_back(x);
    g.alpha.push_back(ltc_alpha_at(x));
  }
  g.convention = fmt::format(
      "endpoints (Heitz's fitLTC): nov = cos(min(acos(1 - (i/{0})^2), 1.57)), perceptual_roughness "
      "= j/{0}, "
      "alpha = max(perceptual_roughness^2, {1:g})",
      size - 1, kLtcMinAlpha);
  return g;
}

std::vector<brdf::DiskPoint> lobe_disk_points(int samples) {
  check_samples(samples);
  std::vector<brdf::DiskPoint> points;
  points.reserve(static_cast<size_t>(samples));
  for (int k = 0; k < samples; ++k) {
    const auto u =
        brdf::hammersley(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(samples));
    points.push_back(brdf::disk_point(u.u1, u.u2));
  }
  return points;
}

FL_FLATTEN void lobe_samples(const LobeView& view, const brdf::DiskPoint* points, size_t count,
                             LobeSampleBlock& out) {
  const LobeView local =
      view;  // a local copy: its reads cannot fault, so the loop runs branch-free
  for (size_t k = 0; k < count; ++k) {
    const brdf::Vec3 h = local.vndf(points[k]);
    const brdf::Vec3 l = brdf::reflect(local.v, h);
    const double voh = std::clamp(brdf::dot(local.v, h), 0.0, 1.0), w = local.weight(l.z);
    out.lx[k] = l.x, out.ly[k] = l.y, out.lz[k] = l.z, out.voh[k] = voh, out.weight[k] = w;
  }
}

DfgTexel integrate_dfg(double nov, double alpha, const std::vector<brdf::DiskPoint>& points) {
  DfgTexel t;
  for_each_lobe_sample(nov, alpha, points, [&](const LobeSample& s) {
    const double m = 1.0 - s.voh;
    const double fc = pow5(m);
    for (const auto& term : fresnel::kTermRegistry)
      t[term.term] += fresnel::dfg_kernel(term.term, s.voh, m, fc) * s.weight;
  });
  const double samples = static_cast<double>(points.size());
  for (double& c : t.v) c /= samples;
  return t;
}
DfgTexel integrate_dfg(double nov, double alpha, int samples) {
  return integrate_dfg(nov, alpha, lobe_disk_points(samples));
}

double integrate_sheen_dfg(double nov, double alpha, int samples) {
  check_samples(samples);
  const brdf::Vec3 v = brdf::view_from_nov(nov);
  double sum = 0;
  for (int k = 0; k < samples; ++k) {
    const auto u =
        brdf::hammersley(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(samples));
    const double phi = 2.0 * std::numbers::pi * u.u1, cos_h = 1.0 - u.u2,
                 sin_h = std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h));
    const brdf::Vec3 h{sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h};
    const double voh = brdf::dot(v, h);
    const brdf::Vec3 l = brdf::reflect(v, h);
    if (voh <= 0.0 || l.z <= 0.0) continue;
    // f (n·l) dω_l = D V (n·l) 4 (v·h) dω_h, and dω_h / pdf = 2π.
    sum += brdf::charlie_ndf(cos_h, alpha) * brdf::neubelt_visibility(v.z, l.z) * l.z * 4.0 * voh;
  }
  return sum * 2.0 * std::numbers::pi / samples;
}

namespace {

// The terms of integrate_moments' sums for a block of samples, as columns; 0 for a direction below
// the horizon, which adds nothing to a sum.
struct MomentTerms {
  double m1[kLobeBlock], m5[kLobeBlock];  // 1 − v·h and its fifth power, shared by the terms
  double term[fresnel::kTermCount][kLobeBlock], dir_x[kLobeBlock], dir_z[kLobeBlock];
};
// Term I of the registry over a block: its kernel is known at compile time, so it is inlined and
// the loop computes several samples per instruction.
template <size_t I>
void moment_term(const LobeSampleBlock& b, size_t count, MomentTerms& t) {
  constexpr fresnel::TermKernel kernel = fresnel::kTermRegistry[I].kernel;
  for (size_t k = 0; k < count; ++k) {
    const double value = kernel(b.voh[k], t.m1[k], t.m5[k]) * b.weight[k];
    t.term[I][k] = b.weight[k] <= 0.0 ? 0.0 : value;
  }
}
template <size_t... I>
FL_FLATTEN void moment_terms(const LobeSampleBlock& b, size_t count, MomentTerms& t,
                             std::index_sequence<I...>) {
  for (size_t k = 0; k < count; ++k) {
    const double w = b.weight[k];
    t.m1[k] = 1.0 - b.voh[k];
    t.m5[k] = pow5(t.m1[k]);
    t.dir_x[k] = w <= 0.0 ? 0.0 : b.lx[k] * w;
    t.dir_z[k] = w <= 0.0 ? 0.0 : b.lz[k] * w;
  }
  (moment_term<I>(b, count, t), ...);
}

}  // namespace

GgxMoments integrate_moments(double nov, double alpha, const std::vector<brdf::DiskPoint>& points) {
  GgxMoments m;
  double sum[fresnel::kTermCount] = {};
  brdf::Vec3 dir{0, 0, 0};
  MomentTerms t;
  for_each_lobe_block(nov, alpha, points, [&](const LobeSampleBlock& b, size_t count) {
    moment_terms(b, count, t, std::make_index_sequence<fresnel::kTermCount>());
    for (size_t k = 0; k < count; ++k) {
      for (size_t i = 0; i < fresnel::kTermCount; ++i) sum[i] += t.term[i][k];
      dir.x += t.dir_x[k], dir.z += t.dir_z[k];
    }
  });
  const double samples = static_cast<double>(points.size());
  for (size_t i = 0; i < fresnel::kTermCount; ++i) m.v[i] = sum[i] / samples;
  // The lobe of an isotropic BRDF is symmetric about the xz-plane: the mean direction has y = 0.
  m.average_dir =
      (dir.x * dir.x + dir.z * dir.z > 0.0) ? brdf::normalize(dir) : brdf::Vec3{0, 0, 1};
  return m;
}
GgxMoments integrate_moments(double nov, double alpha, int samples) {
  return integrate_moments(nov, alpha, lobe_disk_points(samples));
}

namespace {

// Every cell of the grid, integrand(n·v, α), filled in parallel column by column; each
// cell counts once in `done`.
template <class Cell, class Integrand>
std::vector<Cell> integrate_grid(const LutGrid& grid, const LutOptions& options,
                                 Integrand integrand, ProgressCounter& done) {
  check_samples(options.samples);
  std::vector<Cell> cells(static_cast<size_t>(grid.size) * grid.size);
  parallel_for(
      grid.size,
      [&](size_t j) {
        for (int i = 0; i < grid.size; ++i)
          cells[grid.index(i, static_cast<int>(j))] = integrand(grid.nov[i], grid.alpha[j]);
        done.add(grid.size);
      },
      options.threads);
  return cells;
}

// integral(n·v, α, points) over one point set for every cell: lobe_disk_points(options.samples),
// made once.
template <class Cell>
auto lobe_integrand(Cell (*integral)(double, double, const std::vector<brdf::DiskPoint>&),
                    const LutOptions& options) {
  return [integral, points = lobe_disk_points(options.samples)](double nov, double alpha) {
    return integral(nov, alpha, points);
  };
}

}  // namespace

DfgTable dfg_table(const LutGrid& grid, const LutOptions& options) {
  ProgressCounter done(options.progress, grid.size * grid.size);
  return {grid,
          integrate_grid<DfgTexel>(grid, options, lobe_integrand(integrate_dfg, options), done)};
}

std::vector<double> sheen_dfg_table(const LutGrid& grid, const LutOptions& options) {
  ProgressCounter done(options.progress, grid.size * grid.size);
  return integrate_grid<double>(
      grid, options,
      [&](double nov, double alpha) { return integrate_sheen_dfg(nov, alpha, options.samples); },
      done);
}

MomentsTable moments_table(const LutGrid& grid, const LutOptions& options) {
  ProgressCounter done(options.progress, grid.size * grid.size);
  return {grid, integrate_grid<GgxMoments>(grid, options,
                                           lobe_integrand(integrate_moments, options), done)};
}

MomentsTable moments_table(const LutGrid& grid, const LutOptions& options, ProgressCounter& done) {
  return {grid, integrate_grid<GgxMoments>(grid, options,
                                           lobe_integrand(integrate_moments, options), done)};
}

}  // namespace fl::analysis
