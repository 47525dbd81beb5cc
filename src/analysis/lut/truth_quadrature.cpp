#include "analysis/lut/truth_quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::analysis {

namespace {

// Chebyshev–Lobatto points on each panel (Trefethen, "Approximation Theory and Approximation
// Practice", ch. 2: x_i = −cos(iπ/d) on [−1, 1]), mapped onto the panel.
std::array<double, kTruthNodes> make_truth_nodes() {
  std::array<double, kTruthNodes> mu{};
  for (size_t p = 0; p + 1 < kTruthPanelEdges.size(); ++p) {
    const double a = kTruthPanelEdges[p], b = kTruthPanelEdges[p + 1];
    // The extrema of the Chebyshev polynomial T_d on [a, b], the ends exact.
    for (int i = 0; i <= kTruthDegree; ++i)
      mu[p * kTruthDegree + i] =
          i == kTruthDegree
              ? b
              : a + (b - a) * 0.5 * (1.0 - std::cos(std::numbers::pi * i / kTruthDegree));
  }
  return mu;
}

constexpr size_t kTruthPanels = kTruthPanelEdges.size() - 1;
using PanelDenominators = std::array<std::array<double, kTruthDegree + 1>, kTruthPanels>;

// Per panel and node i of it, Π_{j ≠ i} (μ_i − μ_j) over the panel's other nodes: the Lagrange
// basis's denominators (a panel's top node, shared, is the bottom node of the panel above).
PanelDenominators truth_denominators() {
  const auto& mu = truth_nodes();
  PanelDenominators d{};
  for (size_t p = 0; p < kTruthPanels; ++p)
    for (int i = 0; i <= kTruthDegree; ++i) {
      const size_t first = p * kTruthDegree;
      double prod = 1.0;
      for (int j = 0; j <= kTruthDegree; ++j)
        if (j != i) prod *= mu[first + i] - mu[first + j];
      d[p][i] = prod;
    }
  return d;
}

}  // namespace

const std::array<double, kTruthNodes>& truth_nodes() {
  static const auto nodes = make_truth_nodes();
  return nodes;
}

// Lagrange's interpolation formula on the panel's nodes: l_i(μ) = Π_{j ≠ i} (μ − μ_j)/(μ_i − μ_j).
void add_truth_weight(std::vector<double>& nodes, double cos_theta, double weight) {
  static const auto denominators = truth_denominators();
  const double mu = std::clamp(cos_theta, 0.0, 1.0);
  size_t p = 0;
  while (p + 1 < kTruthPanels && mu > kTruthPanelEdges[p + 1]) ++p;
  const size_t first = p * kTruthDegree;
  const auto& x = truth_nodes();
  double diff[kTruthDegree + 1];
  for (int j = 0; j <= kTruthDegree; ++j) diff[j] = mu - x[first + j];
  for (int i = 0; i <= kTruthDegree; ++i) {
    double l = weight;
    for (int j = 0; j <= kTruthDegree; ++j)
      if (j != i) l *= diff[j];
    nodes[first + i] += l / denominators[p][i];
  }
}

}  // namespace fl::analysis
