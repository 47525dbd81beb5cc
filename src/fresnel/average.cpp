#include "fresnel/average.h"

#include <array>
#include <cmath>
#include <numbers>

#include "fresnel/registered_models.h"

namespace fl::fresnel {
namespace {

constexpr int kNodes = 20;
// Panels uniform in s with μ = 1 − (1 − s)², which smooths the (1 − μ)^p endpoint behaviour of
// the exponent models at μ = 1 (p down to 0.5); 32 panels of 20 nodes for the models' kernels.
constexpr int kModelPanels = 32;

struct Rule {
  std::array<double, kNodes> x{}, w{};
};

// Abramowitz & Stegun 25.4.29: the roots of P_n by Newton's method on the recurrence, weights
// 2 / ((1 − x²) P_n'(x)²).
Rule gauss_legendre_rule() {
  Rule r;
  for (int i = 0; i < kNodes; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (kNodes + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= kNodes; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = kNodes * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    r.x[i] = x;
    r.w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return r;
}

}  // namespace

std::vector<AverageNode> hemispherical_average_nodes(int panels, double mu_lo, double mu_hi) {
  static const Rule rule = gauss_legendre_rule();
  // s = 1 − √(1 − μ): the panels' variable (0 and 1 at μ = 0 and 1).
  const double s_lo = 1.0 - std::sqrt(1.0 - mu_lo), s_span = 1.0 - std::sqrt(1.0 - mu_hi) - s_lo;
  std::vector<AverageNode> nodes;
  nodes.reserve(static_cast<size_t>(panels) * kNodes);
  for (int panel = 0; panel < panels; ++panel) {
    const double s0 = s_lo + s_span * panel / panels, half = 0.5 * s_span / panels;
    for (int k = 0; k < kNodes; ++k) {
      const double s = s0 + half * (rule.x[k] + 1.0);
      const double mu = 1.0 - (1.0 - s) * (1.0 - s);
      const double dmu_ds = 2.0 * (1.0 - s);
      nodes.push_back({mu, 2.0 * mu * dmu_ds * half * rule.w[k]});
    }
  }
  return nodes;
}

color::Rgb hemispherical_average_of(const std::function<color::Rgb(double)>& f, int panels) {
  color::Rgb sum{};
  for (const auto& node : hemispherical_average_nodes(panels)) sum = sum + node.weight * f(node.mu);
  return sum;
}

color::Rgb hemispherical_average_quadrature(Model m, const std::vector<double>& params) {
  const auto& spec = model_spec(m);
  return hemispherical_average_of(
      [&](double mu) { return spec.evaluate(mu, params.data(), false); }, kModelPanels);
}

bool average_in_closed_form(Model m, const std::vector<double>& params) {
  const auto& spec = model_spec(m);
  if (!spec.closed_form_average) return false;
  std::vector<double> mu;
  for (int i = 0; i <= 256; ++i) mu.push_back(i / 256.0);
  return !output_clamped(m, params, mu);
}

color::Rgb hemispherical_average(Model m, const std::vector<double>& params) {
  if (!average_in_closed_form(m, params)) return hemispherical_average_quadrature(m, params);
  const auto& spec = model_spec(m);
  color::Rgb out{};
  for (int c = 0; c < 3; ++c) out[c] = spec.closed_form_average(params.data(), c);
  return out;
}

}  // namespace fl::fresnel
