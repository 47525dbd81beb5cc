#pragma once
// CIEDE2000 over many colour pairs at once, in SIMD lanes (bulk use: per-angle error curves,
// benchmarks). Agrees with the templated color::ciede2000 (lab.h) within 1e-12 and with Little CMS
// within 1e-9 (tests/color/test_lcms_agreement.cpp); the template stays the one Ceres
// differentiates.
#include <span>
#include <string>
#include <vector>

#include "color/lab.h"
#include "color/values.h"

namespace fl::color {

// Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference formula": out[i] = ΔE00(lab1[i],
// lab2[i]) with kL = kC = kH = 1, from unit hue vectors, without branches; the widest
// instruction set the CPU has is chosen at run time. Throws std::invalid_argument unless the three
// spans have one length.
void ciede2000_batch(std::span<const Lab> lab1, std::span<const Lab> lab2, std::span<double> out);

// The residuals of ciede2000_residuals (lab.h) between truth[i] and to_lab(rgb[i]), the three per
// angle whose squares sum to ΔE00² (residuals[3i + q]), and their derivatives over rgb[i]:
// d_rgb[(3q + c)·n + i] = d residual q / d channel c, for n = rgb.size(). The same formula as
// ciede2000_batch's, in SIMD lanes with forward-mode derivatives; it agrees with the templated
// ciede2000_residuals within 1e-12 and its derivatives within 1e-9
// (tests/color/test_residuals_batch.cpp). Throws std::invalid_argument unless residuals holds 3 and
// d_rgb 9 values per colour.
void ciede2000_residuals_batch(const LabConverter& to_lab, std::span<const Lab> truth,
                               std::span<const Rgb> rgb, std::span<double> residuals,
                               std::span<double> d_rgb);

// The instruction sets ciede2000_batch is compiled for that this CPU runs, by Highway's names
// ("AVX3", "AVX2", "SSE4", "SSSE3", …), best first.
std::vector<std::string> ciede2000_batch_targets();
// ciede2000_batch on one of those instruction sets, for tests comparing them.
void ciede2000_batch_on(const std::string& target, std::span<const Lab> lab1,
                        std::span<const Lab> lab2, std::span<double> out);
// ciede2000_residuals_batch on one of those instruction sets.
void ciede2000_residuals_batch_on(const std::string& target, const LabConverter& to_lab,
                                  std::span<const Lab> truth, std::span<const Rgb> rgb,
                                  std::span<double> residuals, std::span<double> d_rgb);

}  // namespace fl::color
