#pragma once
// What the tests of the fits' ΔE2000 residuals share: a working space like the fits', and the
// template's residuals on color::Dual (values and derivatives over RGB).
#include "color/dual.h"
#include "color/lab.h"

namespace fl::test {

// Linear Rec.709 → XYZ (IEC 61966-2-1) and the D65 white.
inline const color::LabConverter kRec709ToLab{
    {{0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522, 0.0721750, 0.0193339, 0.1191920,
      0.9503041}},
    {0.95047, 1.0, 1.08883}};

// ciede2000_residuals between the truth and kRec709ToLab(rgb), differentiated over R, G and B.
inline void residuals_dual(const color::Lab& truth, const color::Rgb& rgb, color::Dual<3>* r) {
  using D3 = color::Dual<3>;
  const color::RgbT<D3> v{D3::variable(rgb.r, 0), D3::variable(rgb.g, 1), D3::variable(rgb.b, 2)};
  color::ciede2000_residuals(color::LabT<D3>{truth.L, truth.a, truth.b}, kRec709ToLab(v), r);
}

}  // namespace fl::test
