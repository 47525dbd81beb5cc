#pragma once
// The colour value types: XYZ, RGB and CIELAB triples (templated on the scalar, so that fits can
// differentiate through them) and xy chromaticities.

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
// a + (b − a)·t, per channel.
inline Rgb lerp(const Rgb& a, const Rgb& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}
// The channel-wise product.
inline Rgb mul(const Rgb& a, const Rgb& b) {
  return {a.r * b.r, a.g * b.g, a.b * b.b};
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

}  // namespace fl::color
