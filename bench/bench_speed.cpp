// What every Fresnel model costs, scalar and batched, float and double; the spectral
// ground truth; our CIEDE2000 next to Little CMS's cmsCIE2000DeltaE; each report table's
// generation.
//   bench_speed                                   run everything, console output
//   bench_speed --benchmark_filter=de2000         one group
//   bench_speed --fl_write=REPO                   also write REPO/reports/bench.md and
//                                                 REPO/bench/model_costs.csv (scripts/bench.sh)
// Costs are ns per evaluation (one RGB value at one angle, three channels); with repetitions the
// written files use the median over repetitions of the CPU time.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <lcms2.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "analysis/speed/speed.h"
#include "analysis/tables/table_registry.h"
#include "color/ciede2000_batch.h"
#include "color/lab.h"
#include "documents/table_formats.h"
#include "fresnel/batch.h"
#include "io/writer.h"
#include "util/quantile.h"

namespace {

using fl::fresnel::Model;
constexpr std::size_t kAngles = 4096;  // batch length: a 64×64 texture's worth of angles
constexpr std::size_t kLabPairs = 1024;

template <class T>
std::vector<T> angle_cosines() {
  std::vector<T> c(kAngles);
  for (std::size_t i = 0; i < kAngles; ++i)
    c[i] = static_cast<T>(static_cast<double>(i) / (kAngles - 1));
  return c;
}
template <class T>
std::vector<T> params_of(Model m) {
  std::vector<T> out;
  for (double p : fl::fresnel::example_params(m)) out.push_back(static_cast<T>(p));
  return out;
}

// One call of evaluate_rgb (the model switch inside) per RGB value.
template <class T>
void bm_model_scalar(benchmark::State& state, Model m) {
  const auto cos = angle_cosines<T>();
  const auto p = params_of<T>(m);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kAngles; ++i) {
      auto rgb = fl::fresnel::evaluate_rgb(m, cos[i], p.data());
      benchmark::DoNotOptimize(rgb);
    }
  }
  state.counters["evals"] = static_cast<double>(kAngles);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kAngles));
}

// evaluate_batch over kAngles angles (planar RGB out).
template <class T>
void bm_model_batched(benchmark::State& state, Model m) {
  const auto cos = angle_cosines<T>();
  const auto p = params_of<T>(m);
  std::vector<T> out(3 * kAngles);
  for (auto _ : state) {
    fl::fresnel::evaluate_batch(m, p.data(), cos.data(), kAngles, out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["evals"] = static_cast<double>(kAngles);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kAngles));
}

// ---- ΔE2000: deterministic pairs spanning CIELAB (plus near-neutral and near-equal ones).
struct LabPairs {
  std::vector<fl::color::Lab> a, b;
  std::vector<cmsCIELab> la, lb;
};
const LabPairs& lab_pairs() {
  static const LabPairs pairs = [] {
    LabPairs p;
    std::mt19937_64 rng(20240601);
    std::uniform_real_distribution<double> L(0.0, 100.0), ab(-110.0, 110.0), d(-3.0, 3.0);
    for (std::size_t i = 0; i < kLabPairs; ++i) {
      const fl::color::Lab x{L(rng), ab(rng), ab(rng)};
      // Half the pairs are close (the ΔE < 3 range tables live in), half anywhere.
      const fl::color::Lab y = i % 2 ? fl::color::Lab{L(rng), ab(rng), ab(rng)}
                                     : fl::color::Lab{x.L + d(rng), x.a + d(rng), x.b + d(rng)};
      p.a.push_back(x);
      p.b.push_back(y);
      p.la.push_back({x.L, x.a, x.b});
      p.lb.push_back({y.L, y.a, y.b});
    }
    return p;
  }();
  return pairs;
}
void bm_de2000_template(benchmark::State& state) {
  const auto& p = lab_pairs();
  for (auto _ : state)
    for (std::size_t i = 0; i < kLabPairs; ++i)
      benchmark::DoNotOptimize(fl::color::ciede2000<double>(p.a[i], p.b[i]));
  state.counters["evals"] = static_cast<double>(kLabPairs);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kLabPairs));
}
void bm_de2000_batch(benchmark::State& state) {
  const auto& p = lab_pairs();
  std::vector<double> out(kLabPairs);
  for (auto _ : state) {
    fl::color::ciede2000_batch(p.a, p.b, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["evals"] = static_cast<double>(kLabPairs);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kLabPairs));
}
void bm_de2000_lcms(benchmark::State& state) {
  const auto& p = lab_pairs();
  for (auto _ : state)
    for (std::size_t i = 0; i < kLabPairs; ++i)
      benchmark::DoNotOptimize(cmsCIE2000DeltaE(&p.la[i], &p.lb[i], 1.0, 1.0, 1.0));
  state.counters["evals"] = static_cast<double>(kLabPairs);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kLabPairs));
}

// ---- The catalog, loaded once for the ground truth and table benchmarks.
struct Catalog {
  fl::analysis::Settings settings;
  std::unique_ptr<fl::analysis::Context> ctx;
  std::vector<fl::analysis::LoadedMaterial> materials;
  std::unique_ptr<fl::analysis::TableInputs> inputs;
  const fl::analysis::LoadedMaterial& gold() const {
    for (const auto& m : materials)
      if (m.material.key == "gold") return m;
    return materials.front();
  }
};
Catalog& catalog() {
  static Catalog c = [] {
    Catalog c;
    c.settings.paths.database = FRESNEL_LAB_DEFAULT_DB;
    c.settings.paths.materials = FRESNEL_LAB_DEFAULT_MATERIALS;
    c.ctx = std::make_unique<fl::analysis::Context>(c.settings);
    c.materials = fl::analysis::load_catalog(*c.ctx);
    c.inputs = std::make_unique<fl::analysis::TableInputs>(*c.ctx, c.materials);
    return c;
  }();
  return c;
}

void bm_ground_truth_rgb(benchmark::State& state) {
  auto& c = catalog();
  const auto& gold = c.gold();
  double cos = 0.5;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fl::analysis::ground_truth_rgb(*c.ctx, gold.ior, cos, 1.0));
    cos = cos > 0.99 ? 0.01 : cos + 0.01;
  }
  state.counters["evals"] = 1;
  state.SetItemsProcessed(state.iterations());
}
void bm_ground_truth_curve(benchmark::State& state) {
  auto& c = catalog();
  const auto& gold = c.gold();
  for (auto _ : state)
    benchmark::DoNotOptimize(fl::analysis::ground_truth_curve(*c.ctx, gold.ior, 1.0));
  state.counters["evals"] = static_cast<double>(c.ctx->cos_thetas().size());
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * c.ctx->cos_thetas().size()));
}
void bm_load_catalog(benchmark::State& state) {
  auto& c = catalog();
  for (auto _ : state) benchmark::DoNotOptimize(fl::analysis::load_catalog(*c.ctx));
}
void bm_studies(benchmark::State& state) {
  auto& c = catalog();
  for (auto _ : state) {
    fl::analysis::StudyOptions o;
    benchmark::DoNotOptimize(fl::analysis::study_materials(*c.ctx, c.materials, o));
  }
}
void bm_table(benchmark::State& state, const fl::analysis::TableSpec* spec) {
  auto& c = catalog();
  c.inputs->studies();  // computed once, outside the timing (bm_studies times it)
  try {
    for (auto _ : state) benchmark::DoNotOptimize(spec->build(*c.inputs));
  } catch (const std::exception& e) {  // e.g. `speed` before bench/model_costs.csv exists
    state.SkipWithError(e.what());
  }
}

void register_all() {
  using benchmark::RegisterBenchmark;
  for (const auto& spec : fl::fresnel::model_specs()) {
    const std::string n = spec.name;
    RegisterBenchmark(("model/" + n + "/float/scalar").c_str(), bm_model_scalar<float>, spec.model);
    RegisterBenchmark(("model/" + n + "/float/batched").c_str(), bm_model_batched<float>,
                      spec.model);
    RegisterBenchmark(("model/" + n + "/double/scalar").c_str(), bm_model_scalar<double>,
                      spec.model);
    RegisterBenchmark(("model/" + n + "/double/batched").c_str(), bm_model_batched<double>,
                      spec.model);
  }
  RegisterBenchmark("de2000/ours_template", bm_de2000_template);
  RegisterBenchmark("de2000/ours_batch", bm_de2000_batch);
  RegisterBenchmark("de2000/lcms", bm_de2000_lcms);
  RegisterBenchmark("ground_truth/rgb_one_angle", bm_ground_truth_rgb);
  RegisterBenchmark("ground_truth/curve_91_angles", bm_ground_truth_curve)
      ->Unit(benchmark::kMicrosecond);
  RegisterBenchmark("tables/load_catalog", bm_load_catalog)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  RegisterBenchmark("tables/studies_all_fits", bm_studies)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1)
      ->UseRealTime();
  for (const auto& spec : fl::analysis::table_specs())
    RegisterBenchmark(("tables/" + std::string(spec.name)).c_str(), bm_table, &spec)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(spec.in_reproduce ? 3 : 1)
        ->UseRealTime();
}

// ---- Collecting results for the report files.
struct Result {
  std::vector<double> seconds_per_iter;  // CPU time, one per repetition
  double evals = 0;
  double median_seconds() const { return fl::median(seconds_per_iter); }
  double ns_per_eval() const { return median_seconds() * 1e9 / (evals > 0 ? evals : 1.0); }
};

class CollectingReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, Result> results;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred) continue;
      auto& res = results[r.run_name.function_name];
      // Kernels: CPU time (robust to a busy machine). Tables: wall time (the fits run on threads).
      const bool wall = r.run_name.function_name.rfind("tables/", 0) == 0;
      res.seconds_per_iter.push_back((wall ? r.GetAdjustedRealTime() : r.GetAdjustedCPUTime()) /
                                     benchmark::GetTimeUnitMultiplier(r.time_unit));
      if (auto it = r.counters.find("evals"); it != r.counters.end()) res.evals = it->second.value;
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const auto p = line.find(':');
      return p == std::string::npos ? line : line.substr(p + 2);
    }
  return "unknown CPU";
}
std::string machine_line() {
  return fmt::format("{}, {} hardware threads, g++ {} ({}), Google Benchmark 1.7, Little CMS {}",
                     cpu_model(), std::thread::hardware_concurrency(), __VERSION__, FL_BENCH_FLAGS,
                     LCMS_VERSION);
}

void write_reports(const std::string& repo, const std::map<std::string, Result>& r,
                   int repetitions) {
  auto ns = [&](const std::string& name) {
    const auto it = r.find(name);
    return it == r.end() ? NAN : it->second.ns_per_eval();
  };
  auto num = [](double v, int d) {
    return std::isfinite(v) ? fl::documents::format_number(v, d) : std::string("n/a");
  };
  const std::string machine = machine_line();
  // bench/model_costs.csv: what `table speed` and `plan` read.
  std::string csv =
      "# Fresnel Lab model costs, written by bench_speed --fl_write (scripts/bench.sh); read by\n"
      "# `table speed` and `plan`. ns per evaluation = one RGB value at one angle, over 4096 "
      "angles, median\n"
      "# CPU time of the repetitions.\n";
  csv += "# machine: " + machine + "\n";
  csv +=
      "model,ns_per_eval_float_batched,ns_per_eval_double_batched,ns_per_eval_float_scalar,ns_per_"
      "eval_double_scalar\n";
  for (const auto& spec : fl::fresnel::model_specs()) {
    const std::string p = std::string("model/") + spec.name;
    csv += fmt::format("{},{},{},{},{}\n", spec.name, num(ns(p + "/float/batched"), 3),
                       num(ns(p + "/double/batched"), 3), num(ns(p + "/float/scalar"), 3),
                       num(ns(p + "/double/scalar"), 3));
  }
  fl::io::write_file_atomic(repo + "/bench/model_costs.csv", csv);

  std::string md = "# Fresnel Lab benchmarks\n\n";
  md +=
      "Written by `scripts/bench.sh` (`bench_speed --fl_write=.`, Google Benchmark). Numbers are "
      "machine-dependent "
      "and are not part of `reproduce`; `table speed` and `plan` read the model costs from the "
      "committed "
      "`bench/model_costs.csv` written in the same run.\n\n";
  md += fmt::format("Machine: {}. Median CPU time of {} repetition(s).\n\n", machine, repetitions);
  md += "## Fresnel models (ns per evaluation: one RGB value at one angle)\n\n";
  md +=
      "Scalar: one `evaluate_rgb` call per value (model switch inside). Batched: `evaluate_batch` "
      "over 4096 angles "
      "(model switch hoisted, planar output).\n\n";
  md +=
      "| model | float batched | float scalar | double batched | double scalar "
      "|\n|---|---|---|---|---|\n";
  for (const auto& spec : fl::fresnel::model_specs()) {
    const std::string p = std::string("model/") + spec.name;
    md += fmt::format("| {} | {} | {} | {} | {} |\n", spec.name, num(ns(p + "/float/batched"), 2),
                      num(ns(p + "/float/scalar"), 2), num(ns(p + "/double/batched"), 2),
                      num(ns(p + "/double/scalar"), 2));
  }
  const double t = ns("de2000/ours_template"), l = ns("de2000/lcms");
  const double bt = ns("de2000/ours_batch");
  md += "\n## CIEDE2000 (ns per colour pair, 1024 pairs across CIELAB)\n\n";
  md += "| implementation | ns per pair | Little CMS time / this |\n|---|---|---|\n";
  md += fmt::format(
      "| Fresnel Lab `color::ciede2000_batch` (double, SIMD, Highway target {}) | {} | {}× |\n",
      fl::color::ciede2000_batch_targets().front(), num(bt, 1), num(l / bt, 2));
  md += fmt::format(
      "| Fresnel Lab `color::ciede2000<double>` (template, differentiable) | {} | {}× |\n",
      num(t, 1), num(l / t, 2));
  md += fmt::format("| Little CMS `cmsCIE2000DeltaE` | {} | 1.00× |\n", num(l, 1));
  md +=
      "\nAgreement: tests/color/test_lcms_agreement.cpp checks both of ours against Little "
      "CMS within 1e-9 on the "
      "34 pairs of Sharma, Wu & Dalal 2005 (the batched kernel on every instruction set the CPU "
      "runs), and the batched kernel against the template within 1e-12 on random pairs across "
      "CIELAB.\n";
  md += "\n## Spectral ground truth (gold)\n\n| what | time |\n|---|---|\n";
  md += fmt::format("| one RGB value at one angle | {} µs |\n",
                    num(ns("ground_truth/rgb_one_angle") / 1e3, 2));
  md += fmt::format("| one curve (91 angles) | {} µs |\n",
                    num(ns("ground_truth/curve_91_angles") * 91 / 1e3, 1));
  md +=
      "\n## Table generation (ms wall time; tables reuse the per-material studies, timed once on "
      "their own)\n\n";
  md += "| step | ms |\n|---|---|\n";
  for (const auto& [name, res] : r)
    if (name.rfind("tables/", 0) == 0)
      md += fmt::format("| {} | {} |\n", name.substr(7), num(res.median_seconds() * 1e3, 2));
  md += "\n## Targets\n\n";
  md += fmt::format("- ΔE2000: ours (template) {} ns, Little CMS {} ns per pair: {}× faster.\n",
                    num(t, 1), num(l, 1), num(l / t, 2));
  md += fmt::format(
      "- ΔE2000 batched: ours {} ns, Little CMS {} ns per pair: {}× faster (target ≥ 5×).\n",
      num(bt, 1), num(l, 1), num(l / bt, 2));
  md += fmt::format("- Batched Schlick in float: {} ns per evaluation (target < 1 ns).\n",
                    num(ns("model/schlick/float/batched"), 3));
  fl::io::write_file_atomic(repo + "/reports/bench.md", md);
  fmt::print(stderr, "bench_speed: wrote {0}/reports/bench.md and {0}/bench/model_costs.csv\n",
             repo);
}

}  // namespace

int main(int argc, char** argv) {
  std::string write_repo;
  int repetitions = 1;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--fl_write=", 0) == 0)
      write_repo = a.substr(11);
    else
      args.push_back(argv[i]);
    if (a.rfind("--benchmark_repetitions=", 0) == 0)
      repetitions = std::max(1, std::atoi(a.c_str() + 24));
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;
  register_all();
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!write_repo.empty()) write_reports(write_repo, reporter.results, repetitions);
  benchmark::Shutdown();
  return 0;
}
