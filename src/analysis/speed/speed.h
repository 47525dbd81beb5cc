#pragma once
// What each Fresnel model costs against what it gets wrong (`table speed`), and the
// per-material choice of the cheapest model within a ΔE2000 budget (`plan`).
//
// Determinism: costs are not timed inside a report. The benchmark (bench/bench_speed.cpp, run by
// scripts/bench.sh) writes bench/model_costs.csv, which is committed; `table speed` and `plan`
// read it, so the same inputs give byte-identical reports. `fresnel-lab speed --measure` times
// the batched kernels live instead (for a quick look on another machine; not reproducible).
#include <optional>
#include <string>
#include <vector>

#include "analysis/lut/rendered.h"
#include "analysis/study/study.h"
#include "fresnel/registered_models.h"
#include "util/table.h"

namespace fl::analysis {

// A model without a row in a cost file is unmeasured: shown as such, never an error (the
// scripts fill the files in). Tables print this word in its cost columns.
inline constexpr const char* kUnmeasured = "unmeasured";

// Cost of one evaluation (one RGB value at one angle) of a model, batched over an array of
// angles, in float: what a shader or a bulk evaluation pays.
struct ModelCost {
  fresnel::Model model;
  double ns_per_eval = 0;
};
struct ModelCosts {
  std::string source;            // the file the costs came from, or "measured live"
  std::string machine;           // '# machine:' line of the file (CPU, cores, compiler)
  std::vector<ModelCost> costs;  // the measured models, model_specs() order
  std::optional<double> ns_per_eval(fresnel::Model m) const;  // nullopt: unmeasured
};

// bench/model_costs.csv: '#' comment lines (one '# machine: …'), then a header whose first two
// columns are model,ns_per_eval_float_batched, then at most one row per model (a model without
// one is unmeasured). InputError (file:line) for anything else.
ModelCosts read_model_costs(const std::string& path);
// read_model_costs(file.path), its source named file.name (the path when empty). The command line
// resolves which file (--costs, $FRESNEL_LAB_COSTS, the tool's bench/model_costs.csv).
ModelCosts load_model_costs(const spectral::DataFile& file);

// Times every model's batched float evaluation (4096 angles) now, on this machine: the least
// time per evaluation over `repeats` runs of at least `min_ms` each. Not deterministic.
ModelCosts measure_model_costs(int repeats = 5, double min_ms = 20.0);

// GPU cost of a model's shader function under one lighting: SPIR-V instructions after
// spirv-opt -O (scripts/gpu_costs.sh), all of them and by kind. Deterministic, so reports use it.
struct GpuCost {
  fresnel::Model model;
  Lighting lighting = Lighting::Punctual;
  int instructions = 0, arithmetic = 0, extended = 0, texture = 0;
};
struct GpuCosts {
  std::string source;          // the file
  std::string tools;           // its '# tools:' line (compiler and optimizer versions)
  std::vector<GpuCost> costs;  // the measured model × lighting pairs
  std::optional<GpuCost> of(fresnel::Model m, Lighting l) const;  // nullopt: unmeasured
};
// bench/gpu_costs.csv: '#' comment lines (one '# tools: …'), the header
// model,lighting,instructions,arithmetic,extended,texture, at most one row per model × lighting
// (a pair without one is unmeasured). InputError (file:line) for anything else.
GpuCosts read_gpu_costs(const std::string& path);
// read_gpu_costs(file.path), its source named file.name (the path when empty); resolved like
// load_model_costs (--gpu-costs, $FRESNEL_LAB_GPU_COSTS, the tool's bench/gpu_costs.csv).
GpuCosts load_gpu_costs(const spectral::DataFile& file);

// One (model, parameter set) candidate with its error statistics over the studied materials.
struct SpeedRow {
  fresnel::Model model;
  bool fitted = false;
  std::optional<double> ns_per_eval;  // nullopt: unmeasured
  double median_rms_de00 = 0, max_rms_de00 = 0;
  bool pareto = false;  // no other row is at least as cheap (CPU ns) and at least as accurate, and
                        // better in one
  std::optional<GpuCost> gpu{};  // the model's function under punctual lights; nullopt: unmeasured
  bool pareto_gpu = false;       // as `pareto`, with the GPU instruction count as the cost
};
// Rows in model_specs() order, derived before fitted. Error over every studied material (the
// catalog's metals and dielectrics); Pareto fronts on (ns_per_eval, median_rms_de00) and
// (GPU instructions, median_rms_de00) among the rows whose cost is measured (an unmeasured row is
// on neither front and dominates nothing).
std::vector<SpeedRow> speed_rows(const std::vector<MaterialStudy>& studies, const ModelCosts& costs,
                                 const GpuCosts& gpu);
Table speed_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                  const ModelCosts& costs, const GpuCosts& gpu);

}  // namespace fl::analysis
