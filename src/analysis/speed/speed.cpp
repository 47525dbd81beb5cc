#include "analysis/speed/speed.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <thread>

#include "fresnel/batch.h"
#include "spectral/text_file.h"
#include "util/errors.h"
#include "util/quantile.h"

namespace fl::analysis {

using fresnel::Model;

std::optional<double> ModelCosts::ns_per_eval(Model m) const {
  for (const auto& c : costs)
    if (c.model == m) return c.ns_per_eval;
  return std::nullopt;
}

namespace {

// The data rows of a comma-separated cost file: '#' lines are comments (the value of a
// "# KEY:" comment goes to `note`), the first other line is the header, which `header_ok` judges
// (`header_error` when it fails, `missing_header` when there is none).
struct CostRow {
  int line_no = 0;
  std::vector<std::string> fields;
};
std::vector<CostRow> cost_file_rows(const std::string& path, std::string_view comment_key,
                                    std::string& note,
                                    const std::function<bool(std::string_view line)>& header_ok,
                                    const std::string& header_error,
                                    const std::string& missing_header) {
  const std::string text = spectral::read_text_file(path);
  std::vector<CostRow> rows;
  bool header = false;
  int line_no = 0;
  for (const auto raw : spectral::split_lines(text)) {
    ++line_no;
    const auto line = spectral::trim(raw);
    if (line.empty()) continue;
    if (line.front() == '#') {
      if (line.substr(0, comment_key.size()) == comment_key)
        note = std::string(spectral::trim(line.substr(comment_key.size())));
      continue;
    }
    if (!header) {
      if (!header_ok(line)) throw InputError(path, line_no, header_error);
      header = true;
      continue;
    }
    CostRow row{line_no, {}};
    for (const auto f : spectral::split_fields(line, ",")) row.fields.emplace_back(f);
    rows.push_back(std::move(row));
  }
  if (!header) throw InputError(path, 0, missing_header);
  return rows;
}

}  // namespace

ModelCosts read_model_costs(const std::string& path) {
  ModelCosts out;
  out.source = path;
  const auto header_ok = [](std::string_view line) {
    const auto f = spectral::split_fields(line, ",");
    return f.size() >= 2 && f[0] == "model" && f[1] == "ns_per_eval_float_batched";
  };
  for (const auto& [line_no, f] :
       cost_file_rows(path, "# machine:", out.machine, header_ok,
                      "header must start with model,ns_per_eval_float_batched",
                      "no header line model,ns_per_eval_float_batched")) {
    if (f.size() < 2)
      throw InputError(path, line_no, "expected model,ns_per_eval_float_batched,...");
    const auto& spec = [&]() -> const fresnel::ModelSpec& {
      try {
        return fresnel::model_from_name(std::string(f[0]));
      } catch (const InputError& e) {
        throw InputError(path, line_no, e.what());
      }
    }();
    double ns = 0;
    if (!spectral::parse_finite(f[1], ns) || ns <= 0)
      throw InputError(path, line_no,
                       fmt::format("cost '{}' must be a positive number of nanoseconds", f[1]));
    for (const auto& c : out.costs)
      if (c.model == spec.model)
        throw InputError(path, line_no, fmt::format("model '{}' listed twice", spec.name));
    out.costs.push_back({spec.model, ns});
  }
  std::vector<ModelCost> ordered;  // model_specs() order; a model without a row is unmeasured
  for (const auto& spec : fresnel::model_specs())
    if (const auto ns = out.ns_per_eval(spec.model)) ordered.push_back({spec.model, *ns});
  out.costs = std::move(ordered);
  return out;
}

std::optional<GpuCost> GpuCosts::of(Model m, Lighting l) const {
  for (const auto& c : costs)
    if (c.model == m && c.lighting == l) return c;
  return std::nullopt;
}

namespace {

constexpr const char* kGpuHeader = "model,lighting,instructions,arithmetic,extended,texture";

GpuCost parse_gpu_row(const std::string& path, int line_no, const std::vector<std::string>& f) {
  if (f.size() != 6) throw InputError(path, line_no, fmt::format("expected {}", kGpuHeader));
  GpuCost c;
  try {
    c.model = fresnel::model_from_name(std::string(f[0])).model;
    c.lighting = lighting_from_name(std::string(f[1]));
  } catch (const InputError& e) {
    throw InputError(path, line_no, e.what());
  }
  int* counts[] = {&c.instructions, &c.arithmetic, &c.extended, &c.texture};
  for (int k = 0; k < 4; ++k) {
    double x = 0;
    if (!spectral::parse_finite(f[2 + k], x) || x < 0 || x != static_cast<int>(x))
      throw InputError(path, line_no,
                       fmt::format("count '{}' must be a non-negative integer", f[2 + k]));
    *counts[k] = static_cast<int>(x);
  }
  return c;
}

}  // namespace

GpuCosts read_gpu_costs(const std::string& path) {
  GpuCosts out;
  out.source = path;
  const auto header_ok = [](std::string_view line) { return line == kGpuHeader; };
  for (const auto& [line_no, f] : cost_file_rows(path, "# tools:", out.tools, header_ok,
                                                 fmt::format("header must be {}", kGpuHeader),
                                                 fmt::format("no header line {}", kGpuHeader))) {
    const auto c = parse_gpu_row(path, line_no, f);
    for (const auto& o : out.costs)
      if (o.model == c.model && o.lighting == c.lighting)
        throw InputError(path, line_no,
                         fmt::format("'{}' under {} listed twice",
                                     fresnel::model_spec(c.model).name, lighting_name(c.lighting)));
    out.costs.push_back(c);
  }
  return out;
}

GpuCosts load_gpu_costs(const spectral::DataFile& file) {
  if (file.path.empty())
    throw InputError("no GPU costs file (bench/gpu_costs.csv) was found; give --gpu-costs");
  auto costs = read_gpu_costs(file.path);
  costs.source = file.name.empty() ? file.path : file.name;
  return costs;
}

ModelCosts load_model_costs(const spectral::DataFile& file) {
  if (file.path.empty())
    throw InputError("no model costs file (bench/model_costs.csv) was found; give --costs");
  auto costs = read_model_costs(file.path);
  costs.source = file.name.empty() ? file.path : file.name;
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
        ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                 .count();
      } while (ms < min_ms);
      best_ns = std::min(best_ns, ms * 1e6 / static_cast<double>(evals));
    }
    costs.costs.push_back({spec.model, best_ns});
  }
  return costs;
}

namespace {

// A row on a front: its cost is measured and no other measured row is at least as cheap and as
// accurate, and better in one.
template <class Cost>
bool on_front(const std::vector<SpeedRow>& rows, const SpeedRow& a, Cost cost) {
  if (!cost(a)) return false;
  return std::none_of(rows.begin(), rows.end(), [&](const SpeedRow& b) {
    if (!cost(b)) return false;
    const bool no_worse = *cost(b) <= *cost(a) && b.median_rms_de00 <= a.median_rms_de00;
    const bool better = *cost(b) < *cost(a) || b.median_rms_de00 < a.median_rms_de00;
    return no_worse && better;
  });
}

void mark_pareto_fronts(std::vector<SpeedRow>& rows) {
  const auto cpu = [](const SpeedRow& r) { return r.ns_per_eval; };
  const auto gpu = [](const SpeedRow& r) -> std::optional<double> {
    if (!r.gpu) return std::nullopt;
    return static_cast<double>(r.gpu->instructions);
  };
  for (auto& a : rows) {
    a.pareto = on_front(rows, a, cpu);
    a.pareto_gpu = on_front(rows, a, gpu);
  }
}

}  // namespace

std::vector<SpeedRow> speed_rows(const std::vector<MaterialStudy>& studies, const ModelCosts& costs,
                                 const GpuCosts& gpu) {
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
      row.gpu = gpu.of(spec.model, Lighting::Punctual);
      row.median_rms_de00 = median(rms);
      row.max_rms_de00 = rms.empty() ? 0 : *std::max_element(rms.begin(), rms.end());
      rows.push_back(row);
    }
  }
  mark_pareto_fronts(rows);
  return rows;
}

namespace {

std::vector<Cell> speed_cells(const SpeedRow& r) {
  const auto count = [&](int GpuCost::*member) -> Cell {
    if (!r.gpu) return std::string(kUnmeasured);
    return static_cast<long long>((*r.gpu).*member);
  };
  const Cell cpu = r.ns_per_eval ? Cell(*r.ns_per_eval) : Cell(std::string(kUnmeasured));
  return {std::string(fresnel::model_spec(r.model).name),
          std::string(r.fitted ? "fitted" : "derived"),
          cpu,
          count(&GpuCost::instructions),
          count(&GpuCost::arithmetic),
          count(&GpuCost::extended),
          r.median_rms_de00,
          r.max_rms_de00,
          std::string(r.pareto ? "yes" : "no"),
          std::string(r.pareto_gpu ? "yes" : "no")};
}

// Names the models without a measured cost, or "" when every one has both.
std::string unmeasured_note(const std::vector<SpeedRow>& rows) {
  std::string cpu, gpu;
  for (const auto& r : rows) {
    if (r.fitted) continue;
    const std::string name = fresnel::model_spec(r.model).name;
    if (!r.ns_per_eval) cpu += (cpu.empty() ? "" : ", ") + name;
    if (!r.gpu) gpu += (gpu.empty() ? "" : ", ") + name;
  }
  if (cpu.empty() && gpu.empty()) return "";
  return fmt::format(
      "unmeasured: no row in the cost files for the CPU cost of {} and the GPU cost of {}; they "
      "are "
      "on neither front until scripts/bench.sh and scripts/gpu_costs.sh measure them.",
      cpu.empty() ? "none" : cpu, gpu.empty() ? "none" : gpu);
}

}  // namespace

Table speed_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                  const ModelCosts& costs, const GpuCosts& gpu) {
  Table t;
  t.name = "speed";
  t.title = "Cost against error: every Fresnel model, derived and fitted parameters";
  t.columns = {{"model"},
               {"parameters"},
               {"cpu_ns_per_eval", 2},
               {"gpu_instructions", 0},
               {"gpu_arithmetic", 0},
               {"gpu_extended", 0},
               {"median_rms_de00", 3},
               {"max_rms_de00", 3},
               {"pareto_cpu"},
               {"pareto_gpu"}};
  const auto rows = speed_rows(studies, costs, gpu);
  std::string front, front_gpu;
  for (const auto& r : rows) {
    t.rows.push_back(speed_cells(r));
    const auto item =
        fmt::format("{} ({})", fresnel::model_spec(r.model).name, r.fitted ? "fitted" : "derived");
    if (r.pareto) front += (front.empty() ? "" : ", ") + item;
    if (r.pareto_gpu) front_gpu += (front_gpu.empty() ? "" : ", ") + item;
  }
  int metals = 0;
  for (const auto& s : studies)
    metals += s.material->material.material_class == spectral::MaterialClass::Metal;
  t.reading = fmt::format(
      "The Pareto front (nothing else is both cheaper and more accurate) on CPU time: {}; on GPU "
      "instructions: {}. "
      "Cost is the same for derived and fitted parameters of a model; fitting only moves a model "
      "down the error axis.",
      front, front_gpu);
  const auto& st = ctx.settings();
  t.notes = {fmt::format("cpu_ns_per_eval: CPU nanoseconds per evaluation (one RGB value at one "
                         "angle, three channels), "
                         "batched over 4096 angles in float, from {} (machine: {}). Regenerate "
                         "with scripts/bench.sh; "
                         "`fresnel-lab speed --measure` times live instead.",
                         costs.source.empty() ? "-" : costs.source,
                         costs.machine.empty() ? "-" : costs.machine),
             fmt::format("gpu_*: SPIR-V instructions of the model's shader function (`fresnel-lab "
                         "shader MODEL`, punctual) "
                         "after spirv-opt -O, all of them, arithmetic and extended (GLSL.std.450: "
                         "pow, sqrt, exp, …), from {} "
                         "({}); deterministic, regenerate with scripts/gpu_costs.sh.",
                         gpu.source, gpu.tools.empty() ? "-" : gpu.tools),
             fmt::format("Error: RMS ΔE2000 over {} angles per material, then the median and max "
                         "over {} catalog materials "
                         "({} metals, {} dielectrics); working space {}, illuminant {}.",
                         st.angles, studies.size(), metals,
                         static_cast<int>(studies.size()) - metals, st.space, st.illuminant),
             "pareto_cpu, pareto_gpu: judged on (cpu_ns_per_eval, median_rms_de00) and "
             "(gpu_instructions, median_rms_de00)."};
  if (const auto note = unmeasured_note(rows); !note.empty()) t.notes.push_back(note);
  return t;
}

}  // namespace fl::analysis
