#pragma once
// Forward-mode derivatives whose values round exactly as plain double arithmetic does.
#include <array>
#include <cmath>

namespace fl::color {

// A value and its derivatives over N inputs. Every operation computes its value with the same
// double operation the plain computation performs (a / b divides, where a Ceres Jet multiplies by
// 1/b), so a template run on Dual<N> gives bit for bit the values it gives on double, and the
// derivatives of those values alongside. The model fits use it to get ΔE2000 residuals and their
// derivatives over RGB in one pass, with residuals identical to the double path's.
template <int N>
struct Dual {
  double v = 0;
  std::array<double, N> d{};

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants enter expressions implicitly, as doubles do
  static Dual variable(double value, int i) {
    Dual x(value);
    x.d[i] = 1.0;
    return x;
  }
  Dual& operator+=(double s) {
    v += s;
    return *this;
  }
  Dual& operator-=(double s) {
    v -= s;
    return *this;
  }
};

namespace detail {
// out.d = a·x.d + b·y.d
template <int N>
Dual<N> with_derivatives(double v, double a, const Dual<N>& x, double b, const Dual<N>& y) {
  Dual<N> out(v);
  for (int i = 0; i < N; ++i) out.d[i] = a * x.d[i] + b * y.d[i];
  return out;
}
template <int N>
Dual<N> with_derivatives(double v, double a, const Dual<N>& x) {
  Dual<N> out(v);
  for (int i = 0; i < N; ++i) out.d[i] = a * x.d[i];
  return out;
}
}  // namespace detail

template <int N>
Dual<N> operator-(const Dual<N>& x) {
  return detail::with_derivatives(-x.v, -1.0, x);
}
template <int N>
Dual<N> operator+(const Dual<N>& x, const Dual<N>& y) {
  return detail::with_derivatives(x.v + y.v, 1.0, x, 1.0, y);
}
template <int N>
Dual<N> operator-(const Dual<N>& x, const Dual<N>& y) {
  return detail::with_derivatives(x.v - y.v, 1.0, x, -1.0, y);
}
template <int N>
Dual<N> operator*(const Dual<N>& x, const Dual<N>& y) {
  return detail::with_derivatives(x.v * y.v, y.v, x, x.v, y);
}
template <int N>
Dual<N> operator/(const Dual<N>& x, const Dual<N>& y) {
  const double q = x.v / y.v;
  return detail::with_derivatives(q, 1.0 / y.v, x, -q / y.v, y);
}
template <int N>
Dual<N> operator+(const Dual<N>& x, double s) {
  Dual<N> out = x;
  out.v = x.v + s;
  return out;
}
template <int N>
Dual<N> operator+(double s, const Dual<N>& x) {
  Dual<N> out = x;
  out.v = s + x.v;
  return out;
}
template <int N>
Dual<N> operator-(const Dual<N>& x, double s) {
  Dual<N> out = x;
  out.v = x.v - s;
  return out;
}
template <int N>
Dual<N> operator-(double s, const Dual<N>& x) {
  return detail::with_derivatives(s - x.v, -1.0, x);
}
template <int N>
Dual<N> operator*(const Dual<N>& x, double s) {
  return detail::with_derivatives(x.v * s, s, x);
}
template <int N>
Dual<N> operator*(double s, const Dual<N>& x) {
  return detail::with_derivatives(s * x.v, s, x);
}
template <int N>
Dual<N> operator/(const Dual<N>& x, double s) {
  return detail::with_derivatives(x.v / s, 1.0 / s, x);
}
template <int N>
Dual<N> operator/(double s, const Dual<N>& x) {
  const double q = s / x.v;
  return detail::with_derivatives(q, -q / x.v, x);
}

template <int N>
bool operator==(const Dual<N>& x, const Dual<N>& y) {
  return x.v == y.v;
}
template <int N>
bool operator<(const Dual<N>& x, const Dual<N>& y) {
  return x.v < y.v;
}
template <int N>
bool operator<=(const Dual<N>& x, const Dual<N>& y) {
  return x.v <= y.v;
}
template <int N>
bool operator>(const Dual<N>& x, const Dual<N>& y) {
  return x.v > y.v;
}
template <int N>
bool operator>=(const Dual<N>& x, const Dual<N>& y) {
  return x.v >= y.v;
}

template <int N>
Dual<N> sqrt(const Dual<N>& x) {
  const double r = std::sqrt(x.v);
  return detail::with_derivatives(r, 0.5 / r, x);
}
template <int N>
Dual<N> cbrt(const Dual<N>& x) {
  const double r = std::cbrt(x.v);
  return detail::with_derivatives(r, 1.0 / (3.0 * r * r), x);
}
template <int N>
Dual<N> exp(const Dual<N>& x) {
  const double e = std::exp(x.v);
  return detail::with_derivatives(e, e, x);
}
template <int N>
Dual<N> sin(const Dual<N>& x) {
  return detail::with_derivatives(std::sin(x.v), std::cos(x.v), x);
}
template <int N>
Dual<N> cos(const Dual<N>& x) {
  return detail::with_derivatives(std::cos(x.v), -std::sin(x.v), x);
}
// d xʸ = y·xʸ⁻¹ dx + ln(x)·xʸ dy, with xʸ⁻¹ as xʸ/x where x > 0 (one pow fewer).
template <int N>
Dual<N> pow(const Dual<N>& x, const Dual<N>& y) {
  const double p = std::pow(x.v, y.v);
  const double dx = x.v > 0.0 ? y.v * p / x.v : y.v * std::pow(x.v, y.v - 1.0);
  return detail::with_derivatives(p, dx, x, x.v > 0.0 ? std::log(x.v) * p : 0.0, y);
}
// d atan2(y, x) = (x dy − y dx) / (x² + y²)
template <int N>
Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
  const double s = 1.0 / (x.v * x.v + y.v * y.v);
  return detail::with_derivatives(std::atan2(y.v, x.v), -y.v * s, x, x.v * s, y);
}

}  // namespace fl::color
