#pragma once
// CIELAB and CIEDE2000, templated on the scalar so Ceres can differentiate a ΔE2000 objective.
#include <cmath>
#include <numbers>

#include "color/autodiff.h"
#include "color/matrix.h"

namespace fl::color {

namespace detail {
template <class T>
T lab_f(const T& t) {
  using std::cbrt;
  // CIE 15:2004: (6/29)³ is the junction of the cube root and its linear toe.
  constexpr double kDelta = 6.0 / 29.0;
  if (t > T(kDelta * kDelta * kDelta)) return cbrt(t);
  return t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}
constexpr double kDegPerRad = 180.0 / std::numbers::pi;
}  // namespace detail

// CIE 1976 L*a*b* relative to `white` (its Y is the reference luminance).
template <class T>
LabT<T> xyz_to_lab(const XyzT<T>& v, const Xyz& white) {
  const T fx = detail::lab_f(v.X / white.X), fy = detail::lab_f(v.Y / white.Y),
          fz = detail::lab_f(v.Z / white.Z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// The weighted terms of CIEDE2000: ΔE00² = l² + c² + h² + rt·c·h.
template <class T>
struct De2000Terms {
  T l, c, h, rt;
};

// Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference formula: implementation notes";
// kL = kC = kH = 1. Hue angles in degrees; 25^7 is the formula's chroma constant.
template <class T>
De2000Terms<T> ciede2000_terms(const LabT<T>& lab1, const LabT<T>& lab2) {
  using detail::kDegPerRad;
  using std::atan2;
  using std::cos;
  using std::exp;
  using std::sin;
  constexpr double k25pow7 = 6103515625.0;  // 25^7
  const T c1 = safe_sqrt(lab1.a * lab1.a + lab1.b * lab1.b);
  const T c2 = safe_sqrt(lab2.a * lab2.a + lab2.b * lab2.b);
  const T c_bar = 0.5 * (c1 + c2);
  const T c_bar7 = c_bar * c_bar * c_bar * c_bar * c_bar * c_bar * c_bar;
  const T g = 0.5 * (1.0 - safe_sqrt(c_bar7 / (c_bar7 + k25pow7)));
  const T a1p = (1.0 + g) * lab1.a, a2p = (1.0 + g) * lab2.a;
  const T c1p = safe_sqrt(a1p * a1p + lab1.b * lab1.b);
  const T c2p = safe_sqrt(a2p * a2p + lab2.b * lab2.b);
  auto hue = [&](const T& b, const T& ap, const T& cp) {
    if (cp <= T(0.0)) return T(0.0);
    T h = atan2(b, ap) * kDegPerRad;
    if (h < T(0.0)) h += 360.0;
    return h;
  };
  const T h1p = hue(lab1.b, a1p, c1p), h2p = hue(lab2.b, a2p, c2p);
  const T dl = lab2.L - lab1.L;
  const T dc = c2p - c1p;
  const T cc = c1p * c2p;
  T dh(0.0);
  if (cc > T(0.0)) {
    dh = h2p - h1p;
    if (dh > T(180.0))
      dh -= 360.0;
    else if (dh < T(-180.0))
      dh += 360.0;
  }
  const T d_big_h = 2.0 * safe_sqrt(cc) * sin(dh / (2.0 * kDegPerRad));
  const T l_bar = 0.5 * (lab1.L + lab2.L);
  const T cp_bar = 0.5 * (c1p + c2p);
  T hp_bar = h1p + h2p;
  if (cc > T(0.0)) {
    const T diff = h1p - h2p;
    if (diff <= T(180.0) && diff >= T(-180.0))
      hp_bar = 0.5 * (h1p + h2p);
    else if (h1p + h2p < T(360.0))
      hp_bar = 0.5 * (h1p + h2p + 360.0);
    else
      hp_bar = 0.5 * (h1p + h2p - 360.0);
  }
  const double r = 1.0 / kDegPerRad;
  const T t = 1.0 - 0.17 * cos((hp_bar - 30.0) * r) + 0.24 * cos(2.0 * hp_bar * r) +
              0.32 * cos((3.0 * hp_bar + 6.0) * r) - 0.20 * cos((4.0 * hp_bar - 63.0) * r);
  const T q = (hp_bar - 275.0) / 25.0;
  const T d_theta = 30.0 * exp(-(q * q));
  const T cp_bar7 = cp_bar * cp_bar * cp_bar * cp_bar * cp_bar * cp_bar * cp_bar;
  const T rc = 2.0 * safe_sqrt(cp_bar7 / (cp_bar7 + k25pow7));
  const T l50 = (l_bar - 50.0) * (l_bar - 50.0);
  const T sl = 1.0 + 0.015 * l50 / safe_sqrt(20.0 + l50);
  const T sc = 1.0 + 0.045 * cp_bar;
  const T sh = 1.0 + 0.015 * cp_bar * t;
  const T rt = -sin(2.0 * d_theta * r) * rc;
  return {dl / sl, dc / sc, d_big_h / sh, rt};
}

template <class T>
T ciede2000(const LabT<T>& lab1, const LabT<T>& lab2) {
  const auto d = ciede2000_terms(lab1, lab2);
  return safe_sqrt(d.l * d.l + d.c * d.c + d.h * d.h + d.rt * d.c * d.h);
}

// Three smooth residuals whose squares sum to ΔE00²: l, c + (rt/2)·h, sqrt(1 − rt²/4)·h
// (|rt| ≤ 2·sin 60° < 2, so the root is real). Least squares on these minimizes Σ ΔE00²
// without the kink that ΔE00 itself has at zero.
template <class T>
void ciede2000_residuals(const LabT<T>& lab1, const LabT<T>& lab2, T* residuals) {
  using std::sqrt;
  const auto d = ciede2000_terms(lab1, lab2);
  residuals[0] = d.l;
  residuals[1] = d.c + 0.5 * d.rt * d.h;
  residuals[2] = sqrt(1.0 - 0.25 * d.rt * d.rt) * d.h;
}

}  // namespace fl::color

namespace fl::color {

// Working-space RGB → CIELAB relative to the space's white, templated for Ceres.
struct LabConverter {
  Mat3 rgb_to_xyz;
  Xyz white;
  template <class T>
  LabT<T> operator()(const RgbT<T>& rgb) const {
    return xyz_to_lab(rgb_to_xyz * rgb, white);
  }
};

}  // namespace fl::color
