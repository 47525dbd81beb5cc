#pragma once
// The hemispherical average F_avg = 2∫₀¹ F(μ) μ dμ per channel that Kulla–Conty energy
// compensation needs (Kulla & Conty 2017), of every model's parameter sets and of the spectral
// ground truth.
#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// The spectral ground truth's F_avg: the average of the reflectance spectrum at each μ, through the
// colour pipeline (the pipeline is linear, so this is the RGB of the spectral average), by
// Gauss–Legendre panels in μ (fresnel::hemispherical_average_of).
color::Rgb ground_truth_average(const Context& ctx, const spectral::ComplexIorSpectrum& ior);

// Every material × model × {derived, fitted}: F_avg per channel (closed form where the unit has
// one and its clamp does not bind, quadrature otherwise), the ground truth's, and the largest
// difference over the channels.
Table averages_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

}  // namespace fl::analysis
