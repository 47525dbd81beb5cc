#include "color/ciede2000_fast.h"

#include <cmath>

#include "color/ciede2000_constants.h"
#include "color/lab.h"

namespace fl::color {

namespace {
using namespace detail;  // the formula's constants (ciede2000_constants.h)

double pow7(double x) {
  const double x2 = x * x;
  return x2 * x2 * x2 * x;
}

// The mean hue h̄′ as (cos, sin): the midpoint of the shorter arc between the unit hue vectors, the
// direction of m = u1 + u2, or, when the hues are more than 90° apart (u1 + u2 loses precision),
// d = u2 − u1 turned by ∓90° (the sign of `cross` = u1 × u2).
void mean_hue(double mx, double my, double m2, double dx, double dy, double d2, double cross,
              double& c, double& s) {
  double bx = mx, by = my, b2 = m2;
  if (m2 < d2) {
    bx = cross > 0.0 ? dy : -dy;
    by = cross > 0.0 ? -dx : dx;
    b2 = d2;
  }
  const double inv_b = 1.0 / std::sqrt(b2);
  c = bx * inv_b;
  s = by * inv_b;
}

// T = 1 − 0.17 cos(h̄′ − 30°) + 0.24 cos 2h̄′ + 0.32 cos(3h̄′ + 6°) − 0.20 cos(4h̄′ − 63°) from
// c = cos h̄′ and s = sin h̄′, through the multiple angles 2h̄′, 3h̄′, 4h̄′.
double t_term(double c, double s) {
  const double c2h = c * c - s * s, s2h = 2.0 * s * c;
  const double c3h = c * (4.0 * c * c - 3.0), s3h = s * (3.0 - 4.0 * s * s);
  const double c4h = c2h * c2h - s2h * s2h, s4h = 2.0 * s2h * c2h;
  return 1.0 - 0.17 * (c * kCos30 + s * kSin30) + 0.24 * c2h + 0.32 * (c3h * kCos6 - s3h * kSin6) -
         0.20 * (c4h * kCos63 + s4h * kSin63);
}

// R_T = −sin(2Δθ)·R_C with Δθ = 30°·exp(−((h̄′ − 275°)/25°)²), h̄′ in [0°, 360°) (not wrapped
// around 275°). For h̄′ in [0°, 134°), 141° or more below 275°, Δθ is under 5e-13° (exp(−31.8))
// and so is its effect on ΔE00: the trigonometry is skipped there.
double rotation_term(double c, double s, double cp_bar) {
  constexpr double kRadPerDeg = 1.0 / detail::kDegPerRad;
  if (s >= 0.0 && c > kCos134) return 0.0;
  double hp_bar = std::atan2(s, c) * detail::kDegPerRad;
  if (hp_bar < 0.0) hp_bar += 360.0;
  const double q = (hp_bar - 275.0) / 25.0;
  const double d_theta = 30.0 * std::exp(-(q * q));
  const double cp_bar7 = pow7(cp_bar);
  const double rc = 2.0 * std::sqrt(cp_bar7 / (cp_bar7 + k25pow7));
  return -std::sin(2.0 * d_theta * kRadPerDeg) * rc;
}

// ΔE00 from ΔL′, ΔC′, ΔH′, the means L̄′ and C̄′, and the T and R_T terms.
double weighted_difference(double dl, double dc, double d_big_h, double l_bar, double cp_bar,
                           double t, double rt) {
  const double l50 = (l_bar - 50.0) * (l_bar - 50.0);
  const double sl = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
  const double sc = 1.0 + 0.045 * cp_bar;
  const double sh = 1.0 + 0.015 * cp_bar * t;
  const double tl = dl / sl, tc = dc / sc, th = d_big_h / sh;
  const double e2 = tl * tl + tc * tc + th * th + rt * tc * th;
  return e2 > 0.0 ? std::sqrt(e2) : 0.0;
}

}  // namespace

double ciede2000_fast(const Lab& lab1, const Lab& lab2) {
  const double c1 = std::sqrt(lab1.a * lab1.a + lab1.b * lab1.b);
  const double c2 = std::sqrt(lab2.a * lab2.a + lab2.b * lab2.b);
  const double c_bar7 = pow7(0.5 * (c1 + c2));
  const double g = 0.5 * (1.0 - std::sqrt(c_bar7 / (c_bar7 + k25pow7)));
  const double a1p = (1.0 + g) * lab1.a, a2p = (1.0 + g) * lab2.a;
  const double c1p = std::sqrt(a1p * a1p + lab1.b * lab1.b);
  const double c2p = std::sqrt(a2p * a2p + lab2.b * lab2.b);
  if (!(c1p > 0.0) || !(c2p > 0.0)) return ciede2000<double>(lab1, lab2);
  // Unit hue vectors u = (a′, b)/C′.
  const double inv_c1p = 1.0 / c1p, inv_c2p = 1.0 / c2p;
  const double u1x = a1p * inv_c1p, u1y = lab1.b * inv_c1p, u2x = a2p * inv_c2p,
               u2y = lab2.b * inv_c2p;
  // ΔH′ = 2·sqrt(C′1·C′2)·sin(Δh′/2) with Δh′ ∈ (−180°, 180°): |u2 − u1| = 2|sin(Δh′/2)|, and the
  // sign of Δh′ is the sign of u1 × u2.
  const double dx = u2x - u1x, dy = u2y - u1y;
  const double d2 = dx * dx + dy * dy;
  const double cross = u1x * u2y - u1y * u2x;
  const double mx = u1x + u2x, my = u1y + u2y;
  const double m2 = mx * mx + my * my;
  if (m2 < d2 && std::abs(cross) < kOppositeHueCross) return ciede2000<double>(lab1, lab2);
  const double d_big_h = std::copysign(std::sqrt(c1p * c2p * d2), cross);
  double c = 0, s = 0;
  mean_hue(mx, my, m2, dx, dy, d2, cross, c, s);
  const double cp_bar = 0.5 * (c1p + c2p);
  return weighted_difference(lab2.L - lab1.L, c2p - c1p, d_big_h, 0.5 * (lab1.L + lab2.L), cp_bar,
                             t_term(c, s), rotation_term(c, s, cp_bar));
}

}  // namespace fl::color
