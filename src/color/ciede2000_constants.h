#pragma once
// Constants of CIEDE2000 (Sharma, Wu & Dalal 2005) for the hue-vector formula of
// ciede2000_batch.cpp.

namespace fl::color::detail {

// cos and sin of the T term's phase offsets (degrees 30, 6, 63), to double precision.
constexpr double kCos30 = 0.8660254037844387, kSin30 = 0.5;
constexpr double kCos6 = 0.9945218953682733, kSin6 = 0.10452846326765347;
constexpr double kCos63 = 0.4539904997395468, kSin63 = 0.8910065241883678;
// cos 134°: hues below 134° are 141° or more from the Δθ term's centre at 275°.
constexpr double kCos134 = -0.6946583704589973;
// Hues opposite to rounding (|u1 × u2| below this, u1 · u2 < 0): the mean hue is the formula's
// convention, not geometry, and the reference path decides.
constexpr double kOppositeHueCross = 1e-14;
constexpr double k25pow7 = 6103515625.0;  // 25^7, the formula's chroma constant

}  // namespace fl::color::detail
