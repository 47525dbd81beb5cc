// LTC table fits: Ceres (Levenberg–Marquardt, the tool's fitter) against Nelder–Mead (the
// derivative-free simplex of Heitz's reference fitLTC.cpp) as the solver of analysis::fit_ltc_cell,
// on the same cells, the same objective and the same warm starts. Prints time per table and the
// mean and max held-out error (LtcCell::fit_error) of both.
//   bench_ltc                       16×16 and 64×64
//   bench_ltc --benchmark_filter=/16
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <vector>

#include "analysis/ltc/ltc_fit.h"
#include "analysis/ltc/ltc_table.h"

namespace {

using fl::analysis::LtcParams;
using fl::analysis::LtcProblem;
using fl::fit::FitResult;

// Nelder & Mead 1965 with the standard coefficients (reflection 1, expansion 2, contraction ½,
// shrink ½), on `dim` parameters. Stops when the simplex's values agree to a relative `tolerance`
// or after `max_evaluations`.
template <size_t N, class F>
std::array<double, N> nelder_mead(const F& f, std::array<double, N> start,
                                  const std::array<double, N>& step, double tolerance,
                                  int max_evaluations, int& evaluations, int& iterations) {
  using Point = std::array<double, N>;
  std::array<Point, N + 1> s;
  std::array<double, N + 1> fs;
  for (size_t i = 0; i <= N; ++i) {
    s[i] = start;
    if (i > 0) s[i][i - 1] += step[i - 1];
    fs[i] = f(s[i]);
  }
  evaluations = N + 1;
  iterations = 0;
  while (evaluations < max_evaluations) {
    ++iterations;
    std::array<size_t, N + 1> order;
    for (size_t i = 0; i <= N; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return fs[a] < fs[b]; });
    const size_t lo = order[0], hi = order[N], nh = order[N - 1];
    if (2.0 * std::abs(fs[hi] - fs[lo]) <=
        tolerance * (std::abs(fs[hi]) + std::abs(fs[lo])) + 1e-300)
      break;
    Point o{};
    for (size_t i = 0; i <= N; ++i)
      if (i != hi)
        for (size_t d = 0; d < N; ++d) o[d] += s[i][d] / N;
    auto along = [&](double t) {
      Point p;
      for (size_t d = 0; d < N; ++d) p[d] = o[d] + t * (o[d] - s[hi][d]);
      return p;
    };
    const Point r = along(1.0);
    const double fr = f(r);
    ++evaluations;
    if (fr < fs[nh]) {
      if (fr < fs[lo]) {
        const Point e = along(2.0);
        const double fe = f(e);
        ++evaluations;
        if (fe < fr) {
          s[hi] = e, fs[hi] = fe;
          continue;
        }
      }
      s[hi] = r, fs[hi] = fr;
      continue;
    }
    const Point c = along(-0.5);
    const double fc = f(c);
    ++evaluations;
    if (fc < fs[hi]) {
      s[hi] = c, fs[hi] = fc;
      continue;
    }
    for (size_t i = 0; i <= N; ++i) {
      if (i == lo) continue;
      for (size_t d = 0; d < N; ++d) s[i][d] = s[lo][d] + 0.5 * (s[i][d] - s[lo][d]);
      fs[i] = f(s[i]);
      ++evaluations;
    }
  }
  const size_t best = static_cast<size_t>(std::min_element(fs.begin(), fs.end()) - fs.begin());
  return s[best];
}

constexpr double kNelderMeadTolerance = 1e-12;
constexpr int kNelderMeadMaxEvaluations = 2000;

// The same solve as analysis::fit_ltc_ceres (objective, bounds, isotropic handling), by
// Nelder–Mead.
FitResult fit_ltc_nelder_mead(const LtcProblem& pr, const LtcParams& start, bool isotropic) {
  auto project = [](LtcParams p) {
    p.m11 = std::clamp(p.m11, fl::analysis::kLtcMinScale, fl::analysis::kLtcMaxScale);
    p.m22 = std::clamp(p.m22, fl::analysis::kLtcMinScale, fl::analysis::kLtcMaxScale);
    p.m13 = std::clamp(p.m13, -fl::analysis::kLtcMaxSkew, fl::analysis::kLtcMaxSkew);
    p.m31 = std::clamp(p.m31, -fl::analysis::kLtcMaxSkew, fl::analysis::kLtcMaxSkew);
    return p;
  };
  // Outside the bounds Ceres never goes; a singular or flipped A (m11 − m13 m31 ≤ 0) is infinitely
  // bad.
  auto objective = [&](const LtcParams& p) {
    return p.m11 - p.m13 * p.m31 > fl::analysis::kLtcMinScale * p.m11
               ? fl::analysis::ltc_objective(pr, p)
               : std::numeric_limits<double>::infinity();
  };
  auto step = [](double x) { return x != 0.0 ? 0.1 * std::abs(x) : 0.05; };
  const LtcParams s0 = project(start);
  FitResult r;
  r.initial_cost = objective(s0);
  int evaluations = 0, iterations = 0;
  LtcParams best;
  if (isotropic) {
    auto f = [&](const std::array<double, 2>& x) {
      return objective(project({x[0], x[1], s0.m13, s0.m31}));
    };
    const auto x =
        nelder_mead<2>(f, {s0.m11, s0.m22}, {step(s0.m11), step(s0.m22)}, kNelderMeadTolerance,
                       kNelderMeadMaxEvaluations, evaluations, iterations);
    best = project({x[0], x[1], s0.m13, s0.m31});
  } else {
    auto f = [&](const std::array<double, 4>& x) {
      return objective(project({x[0], x[1], x[2], x[3]}));
    };
    const auto x =
        nelder_mead<4>(f, {s0.m11, s0.m22, s0.m13, s0.m31},
                       {step(s0.m11), step(s0.m22), step(s0.m13), step(s0.m31)},
                       kNelderMeadTolerance, kNelderMeadMaxEvaluations, evaluations, iterations);
    best = project({x[0], x[1], x[2], x[3]});
  }
  r.parameters = {best.m11, best.m22, best.m13, best.m31};
  r.cost = objective(best);
  r.iterations = iterations;
  r.termination = evaluations >= kNelderMeadMaxEvaluations ? "NO_CONVERGENCE" : "CONVERGENCE";
  r.usable = std::isfinite(r.cost);
  return r;
}

struct Summary {
  std::vector<double> errors;
  double seconds = 0;
};
std::map<std::pair<int, bool>, Summary> g_results;  // (size, ceres) → per-cell fit errors

void BM_LtcTableFit(benchmark::State& state, bool use_ceres) {
  const int size = static_cast<int>(state.range(0));
  fl::analysis::LutOptions options;
  options.threads = 1;  // one core per fitter, so the timings compare the solvers
  Summary summary;
  for (auto _ : state) {
    const auto t = use_ceres
                       ? fl::analysis::fit_ltc_table(size, options, fl::analysis::fit_ltc_ceres)
                       : fl::analysis::fit_ltc_table(size, options, fit_ltc_nelder_mead);
    summary.errors.clear();
    for (const auto& c : t.cells) summary.errors.push_back(c.fit_error);
  }
  double sum = 0, max = 0;
  for (double e : summary.errors) sum += e, max = std::max(max, e);
  state.counters["mean_fit_error"] = sum / summary.errors.size();
  state.counters["max_fit_error"] = max;
  g_results[{size, use_ceres}] = summary;
}

BENCHMARK_CAPTURE(BM_LtcTableFit, ceres, true)
    ->Arg(16)
    ->Arg(64)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_LtcTableFit, nelder_mead, false)
    ->Arg(16)
    ->Arg(64)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for (const auto& [key, ceres] : g_results) {
    if (!key.second) continue;
    const auto it = g_results.find({key.first, false});
    if (it == g_results.end()) continue;
    const auto& nm = it->second;
    double sum_c = 0, sum_n = 0;
    int ceres_better = 0, nm_better = 0;
    for (size_t k = 0; k < ceres.errors.size(); ++k) {
      sum_c += ceres.errors[k];
      sum_n += nm.errors[k];
      if (ceres.errors[k] < nm.errors[k] - 1e-4) ++ceres_better;
      if (nm.errors[k] < ceres.errors[k] - 1e-4) ++nm_better;
    }
    const double n = static_cast<double>(ceres.errors.size());
    std::printf(
        "%dx%d cells: mean held-out error (relative L3) Ceres %.5f, Nelder-Mead %.5f; "
        "cells better by >1e-4: Ceres %d, Nelder-Mead %d\n",
        key.first, key.first, sum_c / n, sum_n / n, ceres_better, nm_better);
  }
  return 0;
}
