#include "analysis/tables/speed.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "fresnel/batch.h"
#include "spectral/errors.h"
#include "spectral/text_file.h"
#include "util/median.h"

namespace fl::analysis {

using fresnel::Model;

double ModelCosts::ns_per_eval(Model m) const {
  for (const auto& c : costs)
    if (c.model == m) return c.ns_per_eval;
  throw std::logic_error("model without a cost");
}

ModelCosts read_model_costs(const std::string& path) {
  const std::string text = spectral::read_text_file(path);
  ModelCosts out;
  out.source = path;
  bool header = false;
  int line_no = 0;
  for (const auto raw : spectral::split_lines(text)) {
    ++line_no;
    const auto line = spectral::trim(raw);
    if (line.empty()) continue;
    if (line.front() == '#') {
      constexpr std::string_view kMachine = "# machine:";
      if (line.substr(0, kMachine.size()) == kMachine) out.machine = std::string(spectral::trim(line.substr(kMachine.size())));
      continue;
    }
    const auto f = spectral::split_fields(line, ",");
    if (!header) {
      if (f.size() < 2 || f[0] != "model" || f[1] != "ns_per_eval_float_batched")
        throw InputError(path, line_no, "header must start with model,ns_per_eval_float_batched");
      header = true;
      continue;
    }
    if (f.size() < 2) throw InputError(path, line_no, "expected model,ns_per_eval_float_batched,...");
    const auto& spec = [&]() -> const fresnel::ModelSpec& {
      try {
        return fresnel::model_from_name(std::string(f[0]));
      } catch (const InputError& e) {
        throw InputError(path, line_no, e.what());
      }
    }();
    double ns = 0;
    if (!spectral::parse_finite(f[1], ns) || ns <= 0)
      throw InputError(path, line_no, fmt::format("cost '{}' must be a positive number of nanoseconds", f[1]));
    for (const auto& c : out.costs)
      if (c.model == spec.model) throw InputError(path, line_no, fmt::format("model '{}' listed twice", spec.name));
    out.costs.push_back({spec.model, ns});
  }
  if (!header) throw InputError(path, 0, "no header line model,ns_per_eval_float_batched");
  for (const auto& spec : fresnel::model_specs()) {
    if (std::none_of(out.costs.begin(), out.costs.end(), [&](const ModelCost& c) { return c.model == spec.model; }))
      throw InputError(path, 0, fmt::format("no cost for model '{}'", spec.name));
  }
  std::vector<ModelCost> ordered;
  for (const auto& spec : fresnel::model_specs()) ordered.push_back({spec.model, out.ns_per_eval(spec.model)});
  out.costs = std::move(ordered);
  return out;
}

ModelCosts load_model_costs(const std::string& path) {
  if (!path.empty()) return read_model_costs(path);
  if (const char* env = std::getenv("FRESNEL_LAB_COSTS"); env && *env) return read_model_costs(env);
  auto costs = read_model_costs(FRESNEL_LAB_DEFAULT_COSTS);
  costs.source = "bench/model_costs.csv";  // the committed file, named the same on every machine
  return costs;
}

ModelCosts measure_model_costs(int repeats, double min_ms) {
  constexpr std::size_t kAngles = 4096;
  std::vector<float> cos_theta(kAngles), out(3 * kAngles);
  for (std::size_t i = 0; i < kAngles; ++i) cos_theta[i] = static_cast<float>(i) / (kAngles - 1);
  ModelCosts costs;
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
        fresnel::evaluate_batch(spec.model, params.data(), cos_theta.data(), kAngles, out.data());
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

std::vector<SpeedRow> speed_rows(const std::vector<MaterialStudy>& studies, const ModelCosts& costs) {
  std::vector<SpeedRow> rows;
  for (const auto& spec : fresnel::model_specs()) {
    for (int fitted = 0; fitted < 2; ++fitted) {
      std::vector<double> rms;
      for (const auto& s : studies) {
        const auto& r = s.result(spec.model);
        rms.push_back(fitted ? r.fitted_error.rms : r.derived_error.rms);
      }
      SpeedRow row;
      row.model = spec.model;
      row.fitted = fitted != 0;
      row.ns_per_eval = costs.ns_per_eval(spec.model);
      row.median_rms_de00 = median(rms);
      row.max_rms_de00 = rms.empty() ? 0 : *std::max_element(rms.begin(), rms.end());
      rows.push_back(row);
    }
  }
  for (auto& a : rows) {
    a.pareto = std::none_of(rows.begin(), rows.end(), [&](const SpeedRow& b) {
      const bool no_worse = b.ns_per_eval <= a.ns_per_eval && b.median_rms_de00 <= a.median_rms_de00;
      const bool better = b.ns_per_eval < a.ns_per_eval || b.median_rms_de00 < a.median_rms_de00;
      return no_worse && better;
    });
  }
  return rows;
}

Table speed_table(const Context& ctx, const std::vector<MaterialStudy>& studies, const ModelCosts& costs) {
  Table t;
  t.name = "speed";
  t.title = "Cost against error: every Fresnel model, derived and fitted parameters";
  t.columns = {{"model"}, {"parameters"}, {"ns_per_eval", 2}, {"median_rms_de00", 3}, {"max_rms_de00", 3}, {"pareto"}};
  const auto rows = speed_rows(studies, costs);
  std::string front;
  for (const auto& r : rows) {
    const auto* name = fresnel::model_spec(r.model).name;
    t.rows.push_back({std::string(name), std::string(r.fitted ? "fitted" : "derived"), r.ns_per_eval,
                      r.median_rms_de00, r.max_rms_de00, std::string(r.pareto ? "yes" : "no")});
    if (r.pareto) front += fmt::format("{}{} ({})", front.empty() ? "" : ", ", name, r.fitted ? "fitted" : "derived");
  }
  int metals = 0;
  for (const auto& s : studies) metals += s.material->material.material_class == spectral::MaterialClass::Metal;
  t.reading = fmt::format(
      "The Pareto front (nothing else is both cheaper and more accurate): {}. Cost is the same for derived and "
      "fitted parameters of a model; fitting only moves a model down the error axis.",
      front);
  const auto& st = ctx.settings();
  t.notes = {
      fmt::format("ns_per_eval: nanoseconds per evaluation (one RGB value at one angle, three channels), batched "
                  "over 4096 angles in float, from {} (machine: {}). Regenerate with scripts/bench.sh; "
                  "`fresnel-lab speed --measure` times live instead.",
                  costs.source.empty() ? "-" : costs.source, costs.machine.empty() ? "-" : costs.machine),
      fmt::format("Error: RMS ΔE2000 over {} angles per material, then the median and max over {} catalog materials "
                  "({} metals, {} dielectrics); working space {}, illuminant {}.",
                  st.angles, studies.size(), metals, static_cast<int>(studies.size()) - metals, st.space, st.illuminant),
      "pareto: judged on (ns_per_eval, median_rms_de00)."};
  return t;
}

}  // namespace fl::analysis
