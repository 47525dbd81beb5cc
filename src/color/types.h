#pragma once
// Small colour value types, templated on the scalar so that Ceres can differentiate through them.
#include <array>

namespace fl::color {

template <class T>
struct XyzT {
  T X{}, Y{}, Z{};
};
template <class T>
struct RgbT {
  T r{}, g{}, b{};
  T& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
  const T& operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
};
template <class T>
struct LabT {
  T L{}, a{}, b{};
};
using Xyz = XyzT<double>;
using Rgb = RgbT<double>;
using Lab = LabT<double>;

inline Rgb operator+(const Rgb& u, const Rgb& v) {
  return {u.r + v.r, u.g + v.g, u.b + v.b};
}
inline Rgb operator*(double s, const Rgb& v) {
  return {s * v.r, s * v.g, s * v.b};
}

struct Chromaticity {
  double x = 0, y = 0;
};
inline Xyz xyz_from_xy(Chromaticity c, double Y = 1.0) {
  return {c.x / c.y * Y, Y, (1.0 - c.x - c.y) / c.y * Y};
}
inline Chromaticity xy_from_xyz(const Xyz& v) {
  const double s = v.X + v.Y + v.Z;
  return {v.X / s, v.Y / s};
}

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
