#include "color/matrix.h"

#include <cmath>
#include <stdexcept>

namespace fl::color {

Mat3 Mat3::operator*(const Mat3& b) const {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += (*this)(i, k) * b(k, j);
      r(i, j) = s;
    }
  return r;
}

Mat3 Mat3::inverse() const {
  const auto& a = m;
  const double c00 = a[4] * a[8] - a[5] * a[7], c01 = a[5] * a[6] - a[3] * a[8],
               c02 = a[3] * a[7] - a[4] * a[6];
  const double det = a[0] * c00 + a[1] * c01 + a[2] * c02;
  if (!(std::abs(det) > 1e-300)) throw std::domain_error("singular 3x3 matrix");
  const double d = 1.0 / det;
  return Mat3{{c00 * d, (a[2] * a[7] - a[1] * a[8]) * d, (a[1] * a[5] - a[2] * a[4]) * d, c01 * d,
               (a[0] * a[8] - a[2] * a[6]) * d, (a[2] * a[3] - a[0] * a[5]) * d, c02 * d,
               (a[1] * a[6] - a[0] * a[7]) * d, (a[0] * a[4] - a[1] * a[3]) * d}};
}

}  // namespace fl::color
