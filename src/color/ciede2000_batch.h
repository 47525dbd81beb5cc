#pragma once
// CIEDE2000 over many colour pairs at once, in SIMD lanes (bulk use: per-angle error curves,
// benchmarks). Agrees with the templated color::ciede2000 (lab.h) within 1e-12 and with Little CMS
// within 1e-9 (tests/color/test_lcms_agreement.cpp); the template stays the one Ceres differentiates.
#include <span>
#include <string>
#include <vector>

#include "color/types.h"

namespace fl::color {

// Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference formula": out[i] = ΔE00(lab1[i], lab2[i])
// with kL = kC = kH = 1 and ciede2000_fast's hue vectors, without branches; the widest instruction
// set the CPU has is chosen at run time. Throws std::invalid_argument unless the three spans have one length.
void ciede2000_batch(std::span<const Lab> lab1, std::span<const Lab> lab2, std::span<double> out);

// The instruction sets ciede2000_batch is compiled for that this CPU runs, by Highway's names
// ("AVX3", "AVX2", "SSE4", "SSSE3", …), best first.
std::vector<std::string> ciede2000_batch_targets();
// ciede2000_batch on one of those instruction sets, for tests comparing them.
void ciede2000_batch_on(const std::string& target, std::span<const Lab> lab1, std::span<const Lab> lab2,
                        std::span<double> out);

}  // namespace fl::color
