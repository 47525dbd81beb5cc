#pragma once
// RGB parameters derived from spectral data: the spectral F0 and F82, point-sampled η, κ (one
// wavelength per channel), η, κ processed as if they were reflectances, and Gulbrandsen's edge
// tint from each. Each model's unit (models/) maps these to its "derived" parameter set.
#include <array>
#include <span>
#include <vector>

#include "color/matrix.h"
#include "fresnel/ground_truth.h"

namespace fl::fresnel {

struct DerivedParameters {
  color::Rgb f0, f82;               // the spectral procedure at 0° and at arccos(1/7)
  color::Rgb f82_tint;              // F82 / Schlick(F0) at arccos(1/7): OpenPBR's specular_color
  color::Rgb eta_ps, kappa_ps;      // point-sampled
  color::Rgb eta_refl, kappa_refl;  // processed as reflectances
  color::Rgb g_refl_eta, g_ps_eta;  // Gulbrandsen g from (F0, Refl. η) and (F0, PS η), unclamped
  double eta_rep = 1,
         kappa_rep = 0;  // Cook-Torrance representative index: luminance (Y) of Refl. η, κ
};

// What a unit's derivation (derive, extra_starts) receives: the spectral procedure's RGB parameters
// and the material's spectral data itself, so that a model can derive its parameters from the
// spectrum or the ground-truth curve (a projection onto a basis, say). Views into the caller's
// data, valid for the call.
struct DeriveInput {
  const DerivedParameters& derived;
  const spectral::ComplexIorSpectrum& ior;  // as measured: absolute, on the pipeline's grid
  double eta_outside = 1;                   // the outside medium's real index
  std::span<const color::Rgb> rgb_weights;  // the colour pipeline: RGB = Σ R(λ)·w(λ) over ior
  std::span<const double> cos_thetas;       // the angles of `truth`
  std::span<const color::Rgb> truth;        // the ground-truth curve (empty when not computed)
};

// Every index is taken relative to the outside medium eta_outside. `rgb_to_xyz` gives the
// luminance row for the representative index.
DerivedParameters derive_parameters(const std::vector<color::Rgb>& rgb_weights,
                                    const color::Mat3& rgb_to_xyz,
                                    const spectral::ComplexIorSpectrum& ior, double eta_outside,
                                    const std::array<double, 3>& point_sample_nm);

}  // namespace fl::fresnel
