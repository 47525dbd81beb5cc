#pragma once
// A double-only CIEDE2000 for one pair at a time (optimizer costs, pairwise spreads); many pairs at
// once go through ciede2000_batch (ciede2000_batch.h). Same result as the templated
// color::ciede2000 (lab.h) within 1e-12 (tests/color/test_lcms_agreement.cpp); the template stays
// the one Ceres differentiates.
#include "color/types.h"

namespace fl::color {

// Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference formula: implementation notes";
// kL = kC = kH = 1. Computed from the unit hue vectors instead of hue angles: one atan2 (for the
// mean hue in degrees, needed by the Δθ term) instead of two, and the four cosines of the T term
// and sin(Δh/2) by vector algebra instead of five trigonometric calls. Achromatic colours and
// opposite hues (where the formula's hue conventions decide) take the reference path.
double ciede2000_fast(const Lab& lab1, const Lab& lab2);

}  // namespace fl::color
