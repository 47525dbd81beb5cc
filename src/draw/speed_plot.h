#pragma once
// The error-against-cost plot of `speed --plot` (reports/speed.png), a Drawing (drawing.h) written
// as PNG, SVG or PDF by the file name's extension.
#include <string>
#include <vector>

#include "analysis/speed/speed.h"
#include "draw/drawing.h"

namespace fl::draw {

// Median RMS ΔE2000 (log scale) against ns per evaluation (log scale): one marker per model and
// parameter set (filled: fitted, hollow: derived) in one qualitative colour per model, each model
// named beside its marker (draw/labels.h), the Pareto front joined by a staircase.
Drawing speed_plot(const std::vector<analysis::SpeedRow>& rows, const LabelFont& font);
// Written with its labels in `font`; InputError for an unknown extension (file_type), checked
// before drawing.
void write_speed_plot(const std::string& path, const std::vector<analysis::SpeedRow>& rows,
                      const LabelFont& font);

}  // namespace fl::draw
