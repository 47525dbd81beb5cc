#pragma once
// The error as rendered of a curve projected on a set of functions (docs/basis.md): the GGX lobe's
// integral of each function by the ground truth's own quadrature at lut-accuracy's shading points
// (what tables of infinite resolution would hold), so that any set, the peer's too, renders without
// tables of its own.
#include <array>
#include <vector>

#include "analysis/lut/rendered.h"
#include "analysis/lut/truth_quadrature.h"

namespace fl::analysis {

struct RenderedSets {
  std::vector<ShadingPoint> points;
  std::vector<std::vector<std::vector<double>>> integrals;  // [set][function][point]
};
// `sets_at_nodes`: each set's functions at the truth's nodes (truth_nodes(), truth_quadrature.h).
RenderedSets rendered_sets(const std::vector<std::vector<std::vector<double>>>& sets_at_nodes,
                           std::vector<ShadingPoint> points);

// RMS over the points of ΔE2000 between the lobe's truth and Σ_t c_t·(lobe integral of function t)
// per channel.
double rendered_rms(const Context& ctx, const std::vector<color::Rgb>& lobe,
                    const std::vector<std::vector<double>>& integrals,
                    const std::array<std::vector<double>, 3>& coefficients);

}  // namespace fl::analysis
