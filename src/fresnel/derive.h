#pragma once
// RGB parameters derived from spectral data (SPEC §3), and each model's "derived" parameter set.
#include <array>
#include <vector>

#include "fresnel/ground_truth.h"
#include "fresnel/model_set.h"

namespace fl::fresnel {

struct DerivedParameters {
  color::Rgb f0, f82;             // the spectral procedure at 0° and at arccos(1/7)
  color::Rgb f82_tint;            // F82 / Schlick(F0) at arccos(1/7): OpenPBR's specular_color
  color::Rgb eta_ps, kappa_ps;    // point-sampled
  color::Rgb eta_refl, kappa_refl;  // processed as reflectances
  color::Rgb g_refl_eta, g_ps_eta;  // Gulbrandsen g from (F0, Refl. η) and (F0, PS η), unclamped
  double eta_rep = 1, kappa_rep = 0;  // Cook-Torrance representative index: luminance (Y) of Refl. η, κ
};

// Every index is taken relative to the outside medium eta_outside. `rgb_to_xyz` gives the
// luminance row for the representative index.
DerivedParameters derive_parameters(const std::vector<color::Rgb>& rgb_weights, const color::Mat3& rgb_to_xyz,
                                    const spectral::ComplexIorSpectrum& ior, double eta_outside,
                                    const std::array<double, 3>& point_sample_nm);

// The model's "derived" parameters: Schlick (F0); generalized Schlick (F0, F90 = 1, p through
// the measured F82); Cook-Torrance (F0, representative index); Lazányi (F0, a from F82, α = 6);
// F82 (F0, F82); Gulbrandsen (F0, g from Refl. η, clamped to [0, 1]); RGB Fresnel (Refl. η, κ).
std::vector<double> derived_model_params(Model m, const DerivedParameters& d);

// Gulbrandsen parameters (F0, g) with g clamped to [0, 1]; `clamped` counts channels moved.
std::vector<double> gulbrandsen_params(const color::Rgb& f0, const color::Rgb& g, int* clamped = nullptr);

}  // namespace fl::fresnel
