#pragma once
// The findings at the top of index.html, each line computed from the tables reproduce builds.
#include <string>
#include <vector>

#include "util/table.h"

namespace fl::jobs {

// Up to five Markdown lines: the best model per class as rendered (lut-accuracy), the talk's
// Schlick values reproduced and where they differ (talk_spread), the ranking of the talk's method
// table (methods), and the speed/error Pareto fronts on the CPU and the GPU (speed). A line whose
// table is not among `tables` is left out.
std::vector<std::string> report_summary(const std::vector<Table>& tables);

}  // namespace fl::jobs
