#pragma once
// Pre-integrated GGX lookup tables: Filament's DFG table, Hill's LTC moments n_D and f_D with an
// F82 moment l_D, on the DFG and LTC grids (the LTC fits themselves: analysis/ltc/ltc_table.h).
// Pure computations; jobs/lut_files.h writes them.
//
// Every integral is over the hemisphere of light directions l of the GGX lobe without Fresnel,
// ρ(v, l)·(n·l) = D(h) V(v, l) (n·l) (brdf/ggx.h), estimated with GGX visible-normal sampling
// (Heitz 2018) at the points of a Hammersley set (deterministic quasi-Monte Carlo).
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/pipeline/context.h"
#include "brdf/ggx.h"
#include "fresnel/table_terms.h"
#include "util/parallel.h"

namespace fl::analysis {

// Quasi-Monte Carlo points per table cell. At 64×64 the DFG and moment tables stay within 2.6e-4
// of an independent quadrature (tests/analysis/test_lut.cpp, FullTablesAgreeWithQuadrature).
constexpr int kLutSamples = 8192;
// Heitz's fitLTC.cpp (ltc_code's current fit/fitLTC.cpp, MIN_ALPHA = 0.00001f; older revisions, on
// other view axes, had 0.0001f) clamps α from below so the lobe stays finite at roughness 0; its
// published table is fitted at α = max(roughness², 1e-5): its first cell is M = diag(2e-5, 2e-5,
// 1).
constexpr double kLtcMinAlpha = 1e-5;

// Where a table's N texels sit on an axis x in [0, 1], and so where a bilinear read of x lands.
enum class TexelPlacement {
  // Texel k holds x = k/(N − 1): the first and last texels hold the axis's ends exactly. A shader
  // reads uv = x·(N − 1)/N + ½/N (texel k's centre is (k + ½)/N).
  Endpoints,
  // Texel k holds x = (k + ½)/N (Filament's DFG convention): a shader reads uv = x, and a read
  // within half a texel of either end clamps to the edge texel, half a texel inside the axis.
  Centres,
};
// The texel coordinate (0: the first texel, N − 1: the last; unclamped) a read of x lands on.
double texel_coordinate(TexelPlacement placement, double x, int texels);

// The axes of a table. Cells are stored roughness-major: cell(i_nov, j_roughness) = cells[j·size +
// i]. `nov` and `perceptual_roughness` hold what each texel holds along its axis; a table an engine
// of another layout ships may have more texels on one axis than the other.
struct LutGrid {
  int size = 0;
  std::vector<double> nov;                               // per i
  std::vector<double> perceptual_roughness;              // per j
  std::vector<double> alpha;                             // per j: the GGX α used for the cell
  TexelPlacement placement = TexelPlacement::Endpoints;  // on both axes
  std::string convention;                                // one line for file headers
  int index(int i_nov, int j_roughness) const { return j_roughness * size + i_nov; }
};

// The DFG and energy textures: endpoints over (n·v, perceptual roughness), n·v = i/(N − 1) (θ
// capped at 1.57 rad, as ltc_grid), roughness j/(N − 1), α = max(roughness², kLtcMinAlpha), so
// roughness 0 and 1 and n·v 1 are read exactly. Shaders read uv = (n·v, roughness)·(N − 1)/N + ½/N.
LutGrid dfg_grid(int size);
// Filament's DFG texture convention (`lut dfg --layout filament`, as its cmgen tool writes it):
// texel centres, nov = (i + ½)/N and perceptual roughness (j + ½)/N, α = roughness²; read at
// uv = (n·v, roughness) with no remapping.
LutGrid filament_dfg_grid(int size);
// Heitz's LTC convention (fitLTC.cpp): endpoints, x_i = i/(N − 1) with n·v = 1 − x² (θ capped at
// 1.57 rad), perceptual roughness j/(N − 1), α = max(roughness², kLtcMinAlpha). Shaders look up
// uv = (roughness, √(1 − n·v))·(N − 1)/N + ½/N.
LutGrid ltc_grid(int size);
// ltc_grid's axes at a texture coordinate in [0, 1]: n·v at x = √(1 − n·v) (θ capped at 1.57 rad),
// and α at perceptual roughness r.
double ltc_nov_at(double x);
double ltc_alpha_at(double roughness);

// The split-sum DFG integrals (Karis 2013; "Physically Based Rendering in Filament",
// "Pre-integration for multiscattering"), with Fc = (1 − v·h)⁵: the scale dfg1 = ∫ (1 − Fc) ρ cos
// dl, the bias dfg2 = ∫ Fc ρ cos dl, and the F82 term dfg_f82 = ∫ μ(1 − μ)⁶ ρ cos dl (μ = v·h), so
// that Schlick integrates to F0·dfg1 + dfg2 and Hoffman's F82 model to F0·dfg1 + dfg2 − a·dfg_f82.
// Filament's multiscatter table holds dfg2 and dfg1 + dfg2 (= ∫ ρ cos).
// The channels per term (fresnel::kTermRegistry: dfg1, dfg2, dfg_f82): texel[Term::One] = dfg1.
struct DfgTexel : fresnel::TermValues {};
// Hill's LTC moments and the F82 moment: n_D = ∫ ρ cos, f_D = ∫ (1 − v·h)⁵ ρ cos,
// l_D = ∫ (v·h)(1 − v·h)⁶ ρ cos, so that Hoffman's F82 model integrates to R0 n_D + (1 − R0) f_D −
// a l_D. average_dir is the lobe's mean direction ∫ l ρ cos / ‖∫ l ρ cos‖ (the LTC frame's Z).
// The moments per term (fresnel::kTermRegistry: n_d, f_d, l_d): moments[Term::One] = n_D.
struct GgxMoments : fresnel::TermValues {
  brdf::Vec3 average_dir{0, 0, 1};
};

// One quasi-Monte Carlo sample of the lobe: l drawn from the visible normals of v, weight G₂/G₁
// (brdf::ggx_vndf_weight) so that the mean of weight·g(l) estimates ∫ g ρ cos dl.
struct LobeSample {
  brdf::Vec3 l;
  double voh = 0, weight = 0;
};
// Hammersley point k of `samples` (brdf::hammersley) on the unit disk (brdf::disk_point), k = 0 …
// samples − 1: the view-independent part of every lobe integral, shared by all the cells of a
// table.
std::vector<brdf::DiskPoint> lobe_disk_points(int samples);
// The samples of one view for up to kLobeBlock points, as columns (one array per quantity, so the
// compiler computes several samples per instruction); a weight of 0 marks a direction below the
// horizon.
constexpr size_t kLobeBlock = 256;
struct LobeSampleBlock {
  double lx[kLobeBlock], ly[kLobeBlock], lz[kLobeBlock], voh[kLobeBlock], weight[kLobeBlock];
};
// The view's part of every sample: v, its visible-normal sampler and its weight G₂/G₁.
struct LobeView {
  brdf::Vec3 v;
  brdf::GgxVndfSampler vndf;
  brdf::GgxVndfWeight weight;
  LobeView(double nov, double alpha)
      : v(brdf::view_from_nov(nov)), vndf(v, alpha), weight(v.z, alpha) {}
};
// The samples of points[0, count), count ≤ kLobeBlock, at one view, with the arithmetic of one
// sample at a time.
void lobe_samples(const LobeView& view, const brdf::DiskPoint* points, size_t count,
                  LobeSampleBlock& out);
// fn(block, count) for the blocks of `points` in order, each of count ≤ kLobeBlock samples.
template <class Fn>
void for_each_lobe_block(double nov, double alpha, const std::vector<brdf::DiskPoint>& points,
                         Fn fn) {
  const LobeView view(nov, alpha);
  LobeSampleBlock b;
  for (size_t first = 0; first < points.size(); first += kLobeBlock) {
    const size_t count = std::min(kLobeBlock, points.size() - first);
    lobe_samples(view, points.data() + first, count, b);
    fn(std::as_const(b), count);
  }
}
// fn(sample) for each point whose direction is above the horizon, in the order of `points`.
template <class Fn>
void for_each_lobe_sample(double nov, double alpha, const std::vector<brdf::DiskPoint>& points,
                          Fn fn) {
  for_each_lobe_block(nov, alpha, points, [&](const LobeSampleBlock& b, size_t count) {
    for (size_t k = 0; k < count; ++k) {
      if (b.weight[k] <= 0.0) continue;
      fn(LobeSample{{b.lx[k], b.ly[k], b.lz[k]}, b.voh[k], b.weight[k]});
    }
  });
}
template <class Fn>
void for_each_lobe_sample(double nov, double alpha, int samples, Fn fn) {
  for_each_lobe_sample(nov, alpha, lobe_disk_points(samples), fn);
}

DfgTexel integrate_dfg(double nov, double alpha, int samples = kLutSamples);
// The directional albedo of Filament's sheen lobe (brdf/sheen.h), ∫ D_charlie V_neubelt (n·l) dl,
// the B channel of Filament's DFG table. Half vectors are drawn uniformly over the hemisphere
// (Hammersley points, density 1/(2π)), as Filament's own generator does: the Charlie lobe is broad.
double integrate_sheen_dfg(double nov, double alpha, int samples = kLutSamples);
GgxMoments integrate_moments(double nov, double alpha, int samples = kLutSamples);
// The same integrals over a shared point set (lobe_disk_points(samples)).
DfgTexel integrate_dfg(double nov, double alpha, const std::vector<brdf::DiskPoint>& points);
GgxMoments integrate_moments(double nov, double alpha, const std::vector<brdf::DiskPoint>& points);

// Progress of a long computation: cells done of total (called from worker threads, one at a time).
using LutProgress = std::function<void(int done, int total)>;
struct LutOptions {
  int samples = kLutSamples;
  int threads = 0;  // 0: every hardware thread
  LutProgress progress;
};

struct DfgTable {
  LutGrid grid;
  std::vector<DfgTexel> cells;
};
struct MomentsTable {
  LutGrid grid;
  std::vector<GgxMoments> cells;
};
DfgTable dfg_table(const LutGrid& grid, const LutOptions& options = {});
// integrate_sheen_dfg over the grid, stored like the cells of a DfgTable.
std::vector<double> sheen_dfg_table(const LutGrid& grid, const LutOptions& options = {});
MomentsTable moments_table(const LutGrid& grid, const LutOptions& options = {});

// moments_table with its cells counted in `done` (a longer computation's progress).
MomentsTable moments_table(const LutGrid& grid, const LutOptions& options, ProgressCounter& done);

}  // namespace fl::analysis
