#pragma once
// The hemispherical average of a Fresnel model, for Kulla–Conty multiple-scattering energy
// compensation (Kulla & Conty 2017, "Revisiting Physically Based Shading at Imageworks"):
// F_avg = 2∫₀¹ F(μ) μ dμ per channel, μ = cos θ.
#include <functional>
#include <vector>

#include "color/values.h"
#include "fresnel/model_spec.h"

namespace fl::fresnel {

// The unit's closed form where it has one and the kernel's output clamp does not change the curve
// (the closed forms integrate the formula); otherwise hemispherical_average_quadrature.
color::Rgb hemispherical_average(Model m, const std::vector<double>& params);
// Gauss–Legendre on panels of the kernel itself (accurate to ~1e-12 for the registry's models).
color::Rgb hemispherical_average_quadrature(Model m, const std::vector<double>& params);
// 2∫₀¹ f(μ) μ dμ per channel of any curve, by the same rule on `panels` panels (32 for the models'
// kernels; a smooth curve such as the spectral ground truth needs far fewer).
color::Rgb hemispherical_average_of(const std::function<color::Rgb(double)>& f, int panels = 32);
// The rule of hemispherical_average_of: 2∫₀¹ f(μ) μ dμ ≈ Σ weight·f(mu) over the nodes, in
// order; for integrands that share work between curves (several at each μ). Over [mu_lo, mu_hi]
// instead, the same panels between the ends' s = 1 − √(1 − μ): an integrand with a kink (the
// critical angle of total internal reflection) integrates on either side of it.
struct AverageNode {
  double mu, weight;
};
std::vector<AverageNode> hemispherical_average_nodes(int panels = 32, double mu_lo = 0.0,
                                                     double mu_hi = 1.0);
// Whether hemispherical_average uses the unit's closed form for these parameters.
bool average_in_closed_form(Model m, const std::vector<double>& params);

}  // namespace fl::fresnel
