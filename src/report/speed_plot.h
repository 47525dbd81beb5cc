#pragma once
// Issue 6: the error-against-cost plot of `table speed` (PNG), drawn with a small built-in
// bitmap font so the figure is byte-identical for the same rows on any machine.
#include <string>
#include <vector>

#include "analysis/speed.h"
#include "report/image.h"

namespace fl::report {

// InputError unless `path` ends in .png (checked before any work).
void check_png_path(const std::string& path);

// Median RMS ΔE2000 (log scale) against ns per evaluation (log scale): one marker per model and
// parameter set (filled: fitted, hollow: derived), the Pareto front joined by a line.
Image8 speed_plot(const std::vector<analysis::SpeedRow>& rows);
void write_speed_plot(const std::string& path, const std::vector<analysis::SpeedRow>& rows);

}  // namespace fl::report
