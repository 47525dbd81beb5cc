// `speed`: the cost-against-error table with its plot, from the committed costs or timed live.
#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>

#include "cli/app.h"
#include "cli/costs.h"
#include "cli/table_registry.h"
#include "fresnel/batch.h"
#include "report/speed_plot.h"
#include "report/writer.h"

namespace fl::cli {

analysis::ModelCosts load_model_costs(const std::string& path) {
  if (!path.empty()) return analysis::read_model_costs(path);
  if (const char* env = std::getenv("FRESNEL_LAB_COSTS"); env && *env) return analysis::read_model_costs(env);
  auto costs = analysis::read_model_costs(FRESNEL_LAB_DEFAULT_COSTS);
  costs.source = "bench/model_costs.csv";  // the committed file, named the same on every machine
  return costs;
}

analysis::ModelCosts measure_model_costs(int repeats, double min_ms) {
  constexpr std::size_t kAngles = 4096;
  std::vector<float> cos_theta(kAngles), out(3 * kAngles);
  for (std::size_t i = 0; i < kAngles; ++i) cos_theta[i] = static_cast<float>(i) / (kAngles - 1);
  analysis::ModelCosts costs;
  costs.source = "measured live (speed --measure)";
  costs.machine = fmt::format("{} hardware threads", std::thread::hardware_concurrency());
  volatile float sink = 0;
  for (const auto& spec : fresnel::model_specs()) {
    std::vector<float> params;
    for (double p : fresnel::example_params(spec.model)) params.push_back(static_cast<float>(p));
    double best_ns = 1e300;
    for (int r = 0; r < repeats; ++r) {
      long long evals = 0;
      const auto t0 = std::chrono::steady_clock::now();
      double ms = 0;
      do {
        fresnel::evaluate_batch(spec.model, params.data(), cos_theta.data(), kAngles,
                                       out.data());
        sink = sink + out[kAngles / 2];
        evals += kAngles;
        ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      } while (ms < min_ms);
      best_ns = std::min(best_ns, ms * 1e6 / static_cast<double>(evals));
    }
    costs.costs.push_back({spec.model, best_ns});
  }
  return costs;
}

namespace {

void add_speed(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "speed", "every Fresnel model's cost per evaluation against its ΔE2000 error (table speed), with a plot");
  struct Args {
    std::string format = "csv", costs, plot;
    bool measure = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--format", a->format, "csv, md or json")->capture_default_str();
  sub->add_option("--costs", a->costs, "model costs file (default $FRESNEL_LAB_COSTS or the committed bench/model_costs.csv)");
  sub->add_flag("--measure", a->measure, "time the batched kernels now instead of reading the costs file (not reproducible)");
  sub->add_option("--plot", a->plot, "also write the error-against-cost plot to this file (.png, .svg or .pdf)");
  sub->callback([&g, &selected, a] {
    selected = [&g, a] {
      const auto f = report::format_from_name(a->format);
      if (!a->plot.empty()) report::file_type(a->plot);
      const auto costs = a->measure ? measure_model_costs() : load_model_costs(a->costs);
      const auto ctx = make_context(g);
      const auto ms = analysis::load_catalog(ctx);
      print_warnings(g, ms);
      TableInputs in(ctx, ms, g);
      const auto t = analysis::speed_table(ctx, in.studies(), costs);
      if (!a->plot.empty()) {
        report::write_speed_plot(a->plot, analysis::speed_rows(in.studies(), costs));
        progress(g, "speed: wrote " + a->plot);
      }
      fmt::print("{}", report::render(t, f));
      return 0;
    };
  });
}

}  // namespace

void add_speed_command(CLI::App& app, GlobalOptions& g, Runner& selected) { add_speed(app, g, selected); }

}  // namespace fl::cli
