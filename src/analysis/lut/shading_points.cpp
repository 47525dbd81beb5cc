// The shading points of the rendered error (rendered.h): their lobes' weights on the truth's
// quadrature nodes, their exact integrals, and the engine's bilinear reads of the tables.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "analysis/lut/rendered.h"
#include "util/parallel.h"

namespace fl::analysis {

namespace {

// A bilinear read of a texture: texel coordinate x along i (n·v) and y along j (roughness), clamped
// to the edge texels; the four texels and their weights.
struct Bilinear {
  int i0, i1, j0, j1;
  double fx, fy;
};
void bilinear_axis(double t, int texels, int& k0, int& k1, double& f) {
  t = std::clamp(t, 0.0, static_cast<double>(texels - 1));
  k0 = std::min(static_cast<int>(t), texels - 2);
  k1 = k0 + 1;
  f = t - k0;
}
// The read of `grid` at axis positions (x along i, y along j) in [0, 1].
Bilinear bilinear(const LutGrid& grid, double x, double y) {
  const int ni = static_cast<int>(grid.nov.size()),
            nj = static_cast<int>(grid.perceptual_roughness.size());
  Bilinear b{};
  bilinear_axis(texel_coordinate(grid.placement, x, ni), ni, b.i0, b.i1, b.fx);
  bilinear_axis(texel_coordinate(grid.placement, y, nj), nj, b.j0, b.j1, b.fy);
  return b;
}

// Texels of one table, integrated on first use and stored as the engine's textures store them.
template <class Cell, class Integrate>
class TexelCache {
 public:
  TexelCache(const LutGrid& grid, Integrate integrate) : grid_(grid), integrate_(integrate) {}
  const LutGrid& grid() const { return grid_; }
  void request(int i, int j) { cells_.emplace(std::make_pair(i, j), Cell{}); }
  void compute(int threads) {
    std::vector<std::pair<const std::pair<int, int>, Cell>*> todo;
    for (auto& kv : cells_) todo.push_back(&kv);
    parallel_for(
        todo.size(),
        [&](size_t k) {
          const auto [i, j] = todo[k]->first;
          todo[k]->second = integrate_(grid_.nov[i], grid_.alpha[j]);
        },
        threads);
  }
  const Cell& at(int i, int j) const { return cells_.at({i, j}); }

 private:
  LutGrid grid_;
  Integrate integrate_;
  std::map<std::pair<int, int>, Cell> cells_;
};

template <class Cell>
Cell stored(TexelStorage s, Cell c) {
  for (double& v : c.v) v = stored_texel(s, v);
  return c;
}

// Texel coordinates of a point: the DFG over (n·v, roughness), the LTC moments over
// (√(1 − n·v), roughness).
Bilinear dfg_read(const EngineTables& t, const ShadingPoint& p) {
  return bilinear(t.dfg, p.nov, p.roughness);
}
Bilinear ltc_read(const EngineTables& t, const ShadingPoint& p) {
  return bilinear(t.ltc, std::sqrt(std::max(0.0, 1.0 - p.nov)), p.roughness);
}

template <class Fn>
void for_texels(const Bilinear& b, Fn fn) {
  fn(b.i0, b.j0, (1 - b.fx) * (1 - b.fy));
  fn(b.i1, b.j0, b.fx * (1 - b.fy));
  fn(b.i0, b.j1, (1 - b.fx) * b.fy);
  fn(b.i1, b.j1, b.fx * b.fy);
}

}  // namespace

namespace {

std::vector<ShadingPoint> points_at(const std::vector<double>& roughness) {
  std::vector<ShadingPoint> points;
  for (double r : roughness)
    for (double deg : kShadingViewDeg) {
      ShadingPoint p;
      p.roughness = r;
      p.view_deg = deg;
      p.nov = std::cos(deg * std::numbers::pi / 180.0);
      p.alpha = ltc_alpha_at(r);
      p.mirror = r == 0.0;
      points.push_back(std::move(p));
    }
  return points;
}

// The point's lobe: its weights on the truth curve's nodes and its exact integrals.
void integrate_point(ShadingPoint& p, const std::vector<brdf::DiskPoint>& disk) {
  if (p.mirror) return;  // the truth is the curve at n·v
  p.truth_weights.assign(kTruthNodes, 0.0);
  for_each_lobe_sample(p.nov, p.alpha, disk, [&](const LobeSample& s) {
    if (s.weight != 0.0) add_truth_weight(p.truth_weights, s.voh, s.weight / kLutSamples);
  });
  p.dfg_exact = integrate_dfg(p.nov, p.alpha, disk);
  p.ltc_exact = integrate_moments(p.nov, p.alpha, disk);
}

}  // namespace

namespace {

// Fills in the truth weights, the exact integrals and the table reads of points whose angles are
// set.
void complete_points(std::vector<ShadingPoint>& points, int threads, const EngineTables& tables) {
  // One point set serves every texel and point (lobe_disk_points(kLutSamples), as each would draw).
  const auto disk = lobe_disk_points(kLutSamples);
  const auto dfg_cell = [&](double nov, double alpha) {
    return stored(tables.storage, integrate_dfg(nov, alpha, disk));
  };
  const auto ltc_cell = [&](double nov, double alpha) {
    return stored(tables.storage, integrate_moments(nov, alpha, disk));
  };
  TexelCache<DfgTexel, decltype(dfg_cell)> dfg(tables.dfg, dfg_cell);
  TexelCache<GgxMoments, decltype(ltc_cell)> ltc(tables.ltc, ltc_cell);
  for (const auto& p : points) {
    if (p.mirror) continue;
    for_texels(dfg_read(tables, p), [&](int i, int j, double) { dfg.request(i, j); });
    for_texels(ltc_read(tables, p), [&](int i, int j, double) { ltc.request(i, j); });
  }
  dfg.compute(threads);
  ltc.compute(threads);
  parallel_for(
      points.size(),
      [&](size_t k) {
        auto& p = points[k];
        integrate_point(p, disk);
        if (p.mirror) return;
        for_texels(dfg_read(tables, p), [&](int i, int j, double w) {
          const auto& c = dfg.at(i, j);
          for (size_t t = 0; t < fresnel::kTermCount; ++t) p.dfg.v[t] += w * c.v[t];
        });
        for_texels(ltc_read(tables, p), [&](int i, int j, double w) {
          const auto& c = ltc.at(i, j);
          for (size_t t = 0; t < fresnel::kTermCount; ++t) p.ltc.v[t] += w * c.v[t];
        });
      },
      threads);
}

}  // namespace

std::vector<ShadingPoint> shading_points(const std::vector<double>& roughness, int threads,
                                         const EngineTables& tables) {
  std::vector<ShadingPoint> points = points_at(roughness);
  complete_points(points, threads, tables);
  return points;
}

std::vector<ShadingPoint> shading_points_at(const std::vector<NovRoughness>& at,
                                            bool mirror_at_zero, int threads,
                                            const EngineTables& tables) {
  std::vector<ShadingPoint> points;
  for (const auto& a : at) {
    ShadingPoint p;
    p.roughness = a.roughness;
    p.nov = a.nov;
    p.view_deg = std::acos(std::clamp(a.nov, 0.0, 1.0)) * 180.0 / std::numbers::pi;
    p.alpha = ltc_alpha_at(a.roughness);
    p.mirror = mirror_at_zero && a.roughness == 0.0;
    points.push_back(std::move(p));
  }
  complete_points(points, threads, tables);
  return points;
}

}  // namespace fl::analysis
