#pragma once
// The quadrature in μ = cos θ of the rendered error's truth (rendered.h, lobe_truth): the lobe's
// samples weigh the spectral ground truth at a few nodes of μ, by the interpolating polynomial of
// each sample's panel, so a page's truth needs the spectral curve at those nodes alone.
#include <array>
#include <vector>

namespace fl::analysis {

// The truth's curve in μ = cos θ: the spectral ground truth at kTruthNodes values of μ,
// interpolated per lobe sample by the polynomial of degree kTruthDegree through the nodes of its
// panel. The panels narrow towards grazing, where the curve of a gas (η − 1 ~ 1e-4) turns within a
// few hundredths of μ; each holds the kTruthDegree + 1 Chebyshev–Lobatto points of its span (its
// ends shared with its neighbours). Against the lobe integrated with the spectral curve at every
// sample, within 5e-5 ΔE2000 at the shading points (roughness 0.02 to 1) of every database page
// (tests/analysis/test_lobe_truth.cpp). A mirror's truth is the spectral curve at n·v itself.
inline constexpr std::array<double, 9> kTruthPanelEdges{0.0,   1.0 / 32, 1.0 / 16, 1.0 / 8, 0.25,
                                                        0.375, 0.5,      0.75,     1.0};
inline constexpr int kTruthDegree = 7;
inline constexpr int kTruthNodes =
    (static_cast<int>(kTruthPanelEdges.size()) - 1) * kTruthDegree + 1;
// μ at each node, ascending.
const std::array<double, kTruthNodes>& truth_nodes();
// Adds `weight` × the interpolated curve at cos θ to `nodes` (kTruthNodes weights): the Lagrange
// basis of the panel holding cos θ (clamped to [0, 1]) at cos θ, times `weight`, on that panel's
// nodes.
void add_truth_weight(std::vector<double>& nodes, double cos_theta, double weight);

}  // namespace fl::analysis
