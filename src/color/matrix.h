#pragma once
// The 3×3 matrix of colour conversions (XYZ ↔ RGB, chromatic adaptation, RGB ↔ RGB).
#include <array>

#include "color/values.h"

namespace fl::color {

// Row-major 3×3 matrix.
struct Mat3 {
  std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};

  double operator()(int r, int c) const { return m[3 * r + c]; }
  double& operator()(int r, int c) { return m[3 * r + c]; }

  template <class T>
  std::array<T, 3> apply(const std::array<T, 3>& v) const {
    return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
  }
  template <class T>
  XyzT<T> operator*(const RgbT<T>& v) const {
    const auto o = apply<T>({v.r, v.g, v.b});
    return {o[0], o[1], o[2]};
  }
  template <class T>
  RgbT<T> operator*(const XyzT<T>& v) const {
    const auto o = apply<T>({v.X, v.Y, v.Z});
    return {o[0], o[1], o[2]};
  }
  Mat3 operator*(const Mat3& b) const;
  Mat3 inverse() const;  // throws std::domain_error when singular
  static Mat3 diagonal(double a, double b, double c) { return Mat3{{a, 0, 0, 0, b, 0, 0, 0, c}}; }
};

// RGB → RGB with the same matrix semantics as Mat3 (for conversions between RGB spaces).
inline Rgb transform_rgb(const Mat3& m, const Rgb& v) {
  const auto o = m.apply<double>({v.r, v.g, v.b});
  return {o[0], o[1], o[2]};
}

}  // namespace fl::color
