#pragma once
// The figure of `reports/rendered-library.png`: rendered error over every database page against
// the number of table terms K and against the GPU cost (analysis/library/rendered_library.h).
#include <vector>

#include "analysis/library/rendered_library.h"
#include "draw/drawing.h"

namespace fl::draw {

// Left: the basis projections' median (solid) and p99 (dashed) page RMS ΔE2000 against K = 2..5,
// per class and lighting. Middle (metals) and right (dielectrics): every shader with a measured GPU
// cost, its median over the class's pages against SPIR-V instructions (filled: IBL, hollow: area
// lights), one qualitative colour per shader and each shader named beside its marker where no label
// can cover another (draw/labels.h). Both error axes log scale; labels set in `font`.
Drawing rendered_library_plot(const std::vector<analysis::RenderedLibraryRow>& rows,
                              const LabelFont& font);

}  // namespace fl::draw
