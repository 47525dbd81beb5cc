#pragma once
// Issue 6: the committed model costs (bench/model_costs.csv) that `table speed` and `plan` read,
// and a live timing of the batched kernels for `speed --measure`.
#include <string>

#include "analysis/speed.h"

namespace fl::cli {

// `path`, else $FRESNEL_LAB_COSTS, else the repository's bench/model_costs.csv.
analysis::ModelCosts load_model_costs(const std::string& path = "");

// Times every model's batched float evaluation (4096 angles) now, on this machine: the least
// time per evaluation over `repeats` runs of at least `min_ms` each. Not deterministic.
analysis::ModelCosts measure_model_costs(int repeats = 5, double min_ms = 20.0);

}  // namespace fl::cli
