#include "analysis/basis/optimize_surrogate.h"

#include <algorithm>
#include <cmath>

#include "color/ciede2000_batch.h"
#include "util/parallel.h"
#include "util/quantile.h"

namespace fl::analysis {

using Eigen::MatrixXd;

std::vector<SurrogatePage> surrogate_pages(const Context& ctx,
                                           const std::vector<const LoadedMaterial*>& pages) {
  const size_t n = ctx.cos_thetas().size();
  const color::LabConverter to_lab{ctx.space().rgb_to_xyz, ctx.space().white};
  const std::string baseline = color::ciede2000_batch_targets().back();
  std::vector<SurrogatePage> out(pages.size());
  parallel_for(pages.size(), [&](size_t p) {
    auto& o = out[p];
    o.metal = pages[p]->material.material_class == spectral::MaterialClass::Metal;
    const auto truth = ground_truth_curve(ctx, pages[p]->ior, ctx.settings().eta_outside);
    o.truth.resize(static_cast<Eigen::Index>(n), 3);
    for (size_t j = 0; j < n; ++j)
      for (int c = 0; c < 3; ++c) o.truth(static_cast<Eigen::Index>(j), c) = truth[j][c];
    std::vector<double> residuals(3 * n), d(9 * n);
    // On the baseline instruction set, which every x86-64 CPU runs: the wider ones fuse
    // multiply-adds, and L-BFGS would carry a last-bit difference into the basis.
    color::ciede2000_residuals_batch_on(baseline, to_lab, lab_curve(ctx, truth), truth, residuals,
                                        d);
    o.gram.resize(n);
    for (size_t j = 0; j < n; ++j) {
      // d holds ∂residual_q/∂rgb_c at [(3q + c)·n + j].
      auto g = [&](int a, int b) {
        double sum = 0;
        for (int q = 0; q < 3; ++q) sum += d[(3 * q + a) * n + j] * d[(3 * q + b) * n + j];
        return sum;
      };
      o.gram[j] = {g(0, 0), g(0, 1), g(0, 2), g(1, 1), g(1, 2), g(2, 2)};
    }
  });
  return out;
}

Surrogate::Surrogate(const std::vector<SurrogatePage>& pages, BasisObjective objective)
    : pages_(pages), objective_(objective) {
  for (size_t p = 0; p < pages.size(); ++p) (pages[p].metal ? metals_ : others_).push_back(p);
}

// The products are coefficient-based (lazyProduct): Eigen blocks its general products by the
// CPU's cache sizes, and a blocked sum rounds differently on another CPU.
Surrogate::PageEval Surrogate::evaluate(const SurrogatePage& page, const MatrixXd& b,
                                        const MatrixXd& minv, int free) const {
  const Eigen::Index n = b.rows(), k = b.cols();
  const MatrixXd coef = minv.lazyProduct(b.transpose().lazyProduct(page.truth));  // k × 3
  const MatrixXd r = page.truth - b.lazyProduct(coef);
  MatrixXd g(n, 3);
  PageEval out;
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& G = page.gram[static_cast<size_t>(j)];
    const double r0 = r(j, 0), r1 = r(j, 1), r2 = r(j, 2);
    g(j, 0) = G[0] * r0 + G[1] * r1 + G[2] * r2;
    g(j, 1) = G[1] * r0 + G[3] * r1 + G[4] * r2;
    g(j, 2) = G[2] * r0 + G[4] * r1 + G[5] * r2;
    out.s += r0 * g(j, 0) + r1 * g(j, 1) + r2 * g(j, 2);
  }
  out.s /= static_cast<double>(n);
  if (free == 0) return out;
  // ∂s/∂b for a free column: −2/n (Σ_c coef_c·u_c + v_c·r_c), v = (bᵀb)⁻¹bᵀg, u = g − b·v.
  const MatrixXd v = minv.lazyProduct(b.transpose().lazyProduct(g));
  const MatrixXd u = g - b.lazyProduct(v);
  out.ds_db = MatrixXd::Zero(n, free);
  for (int f = 0; f < free; ++f) {
    const Eigen::Index col = k - free + f;
    for (int c = 0; c < 3; ++c) out.ds_db.col(f) += coef(col, c) * u.col(c) + v(col, c) * r.col(c);
  }
  out.ds_db *= -2.0 / static_cast<double>(n);
  return out;
}

namespace {

// The indices of `pages` in ascending order of s (ties: page order).
std::vector<size_t> ranked(std::vector<size_t> pages, const std::vector<double>& s) {
  std::stable_sort(pages.begin(), pages.end(), [&](size_t a, size_t b) { return s[a] < s[b]; });
  return pages;
}

// The ranks median ± band of n pages, the band narrowed to fit: [first, last].
std::pair<size_t, size_t> median_band(size_t n, int band) {
  const size_t mid = (n + 1) / 2 - 1;
  const size_t b = std::min({static_cast<size_t>(band), mid, n - 1 - mid});
  return {mid - b, mid + b};
}

}  // namespace

double Surrogate::weigh(const std::vector<double>& s, std::vector<double>& d) const {
  const BasisObjective& o = objective_;
  d.assign(s.size(), 0.0);
  double total = 0;
  // a(e) with da/de: add a, and ∂a/∂s = da/de / (2e) (a page the basis fits exactly, e = 0,
  // contributes no gradient).
  auto add = [&](size_t p, double a, double da_de) {
    total += a;
    if (s[p] > 0) d[p] += da_de / (2 * std::sqrt(s[p]));
  };
  auto e = [&](size_t p) { return std::sqrt(s[p]); };
  for (const auto* cls : {&metals_, &others_})
    for (size_t p : *cls) {
      const double w = o.class_mean_weight / static_cast<double>(cls->size());
      add(p, w * e(p), w);
    }
  const auto metals = ranked(metals_, s);
  const size_t m = metals.size();
  for (size_t r = 0; o.tail_weight > 0 && r + o.tail_skip < m; ++r) {
    const double h = e(metals[r]) - o.tail_from, w = o.tail_weight / static_cast<double>(m);
    if (h > 0) add(metals[r], w * h * h, 2 * w * h);
  }
  if (m > 0 && o.metal_median_weight > 0) {
    const auto [first, last] = median_band(m, o.band);
    const double w = o.metal_median_weight / static_cast<double>(last - first + 1);
    for (size_t r = first; r <= last; ++r) add(metals[r], w * e(metals[r]), w);
  }
  // The 4th, 5th, ... worst: ranks m − 4, m − 5, ... ascending.
  for (size_t k = 0; o.metal_rank_weight > 0 && k < static_cast<size_t>(o.metal_ranks); ++k) {
    if (m < 4 + k) break;
    const size_t p = metals[m - 4 - k];
    const double h = e(p) - o.metal_rank_target;
    if (h > 0) add(p, o.metal_rank_weight * h * h, 2 * o.metal_rank_weight * h);
  }
  if (!others_.empty() && o.dielectric_median_weight > 0) {
    const auto others = ranked(others_, s);
    const auto [first, last] = median_band(others.size(), o.band);
    const double count = static_cast<double>(last - first + 1);
    double mean = 0;
    for (size_t r = first; r <= last; ++r) mean += e(others[r]);
    mean /= count;
    const double h = mean - o.dielectric_median_target;
    if (h > 0) {
      total += o.dielectric_median_weight * h * h;
      for (size_t r = first; r <= last; ++r)
        add(others[r], 0, 2 * o.dielectric_median_weight * h / count);
    }
  }
  return total;
}

double Surrogate::value(const MatrixXd& b, int free, MatrixXd* gradient) const {
  const MatrixXd minv = b.transpose().lazyProduct(b).inverse();
  std::vector<PageEval> evals(pages_.size());
  parallel_for(pages_.size(),
               [&](size_t p) { evals[p] = evaluate(pages_[p], b, minv, gradient ? free : 0); });
  std::vector<double> s(pages_.size()), d;
  for (size_t p = 0; p < pages_.size(); ++p) s[p] = evals[p].s;
  const double total = weigh(s, d);
  if (gradient) {
    *gradient = MatrixXd::Zero(b.rows(), free);
    for (size_t p = 0; p < pages_.size(); ++p) *gradient += d[p] * evals[p].ds_db;
  }
  return total;
}

std::vector<double> Surrogate::errors(const MatrixXd& b) const {
  const MatrixXd minv = b.transpose().lazyProduct(b).inverse();
  std::vector<double> e(pages_.size());
  parallel_for(pages_.size(),
               [&](size_t p) { e[p] = std::sqrt(evaluate(pages_[p], b, minv, 0).s); });
  return e;
}

}  // namespace fl::analysis
