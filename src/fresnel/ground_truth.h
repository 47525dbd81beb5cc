#pragma once
// Spectral ground truth and the spectral procedures that derive RGB parameters
// (docs/conventions.md, "Fresnel definitions" and "Deriving RGB parameters").
#include <array>
#include <span>
#include <vector>

#include "color/values.h"
#include "spectral/spectrum.h"

namespace fl::fresnel {

// RGB of the reflectance spectrum at cosθ for the complex index relative to an outside medium of
// real index eta_outside; `rgb_weights` is the colour pipeline (RGB = Σ R(λ)·w(λ)).
color::Rgb spectral_reflectance_rgb(const std::vector<color::Rgb>& rgb_weights,
                                    const spectral::ComplexIorSpectrum& ior, double cos_theta,
                                    double eta_outside);
// The same at every cos_theta[a] into out[a].
void spectral_reflectance_rgb(const std::vector<color::Rgb>& rgb_weights,
                              const spectral::ComplexIorSpectrum& ior,
                              std::span<const double> cos_theta, double eta_outside,
                              color::Rgb* out);

// η(λ) or κ(λ) pushed through the colour pipeline as if it were a reflectance ("Refl. η,κ").
color::Rgb process_as_reflectance(const std::vector<color::Rgb>& rgb_weights,
                                  const spectral::ComplexIorSpectrum& ior, bool kappa);

// η, κ linearly interpolated at one wavelength per channel ("PS η,κ").
struct PointSampled {
  color::Rgb eta, kappa;
};
PointSampled point_sample(const spectral::ComplexIorSpectrum& ior,
                          const std::array<double, 3>& lambda_nm);

// Default point-sampling wavelengths: 630, 532 and 467 nm, the monochromatic primaries of
// Rec.2020 — the nearest thing a wide-gamut RGB space has to one wavelength per channel.
constexpr std::array<double, 3> kDefaultPointSampleNm{630.0, 532.0, 467.0};

// cos θ82 = 1/7 (θ ≈ 81.79°), where Hoffman's F82 model takes its second sample.
constexpr double kCosTheta82 = 1.0 / 7.0;

}  // namespace fl::fresnel
