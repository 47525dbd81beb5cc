// Highway (hwy/foreach_target.h) compiles this file once per x86 instruction set and
// batch_targets() below picks the best one the CPU has; Highway's headers stay in this file.
// Over 400 lines: foreach_target re-includes this one file per instruction set, so the vector
// kernel, its per-target entry points and the dispatch cannot be split across files.
#include "color/ciede2000_batch.h"

#include <cpuid.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "color/ciede2000_constants.h"
#include "color/dual.h"
#include "color/lab.h"

namespace fl::color::detail {
// The template ciede2000<double>, compiled for the baseline instruction set, for the lanes the
// vector formula leaves to it.
double ciede2000_reference(const Lab& lab1, const Lab& lab2);
// ciede2000_residuals<Dual<3>> of the truth and to_lab(rgb), for the lanes the residuals' vector
// formula leaves to it: residuals[q], d_rgb[3q + c] = d residual q / d channel c.
void ciede2000_residuals_reference(const LabConverter& to_lab, const Lab& truth, const Rgb& rgb,
                                   double* residuals, double* d_rgb);
}  // namespace fl::color::detail

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "color/ciede2000_batch.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
// clang-format off
#include "hwy/highway.h"
#include "hwy/contrib/math/math-inl.h"
// clang-format on

HWY_BEFORE_NAMESPACE();
namespace fl::color::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

using namespace detail;  // the formula's constants (ciede2000_constants.h), std::numbers::pi,
                         // kDegPerRad

HWY_INLINE V pow7(V x) {
  const V x2 = hn::Mul(x, x);
  return hn::Mul(hn::Mul(hn::Mul(x2, x2), x2), x);
}

// sqrt(x⁷ / (x⁷ + 25⁷)), the chroma weight of G and R_C.
HWY_INLINE V chroma_weight(D d, V x) {
  const V x7 = pow7(x);
  return hn::Sqrt(hn::Div(x7, hn::Add(x7, hn::Set(d, k25pow7))));
}

// atan2(y, x) in degrees in [0°, 360°), from atan on [0, 1] and the octant.
HWY_INLINE V atan2_deg(D d, V y, V x) {
  const V ax = hn::Abs(x), ay = hn::Abs(y);
  const M steep = hn::Gt(ay, ax);
  const V r = hn::Atan(d, hn::Div(hn::IfThenElse(steep, ax, ay), hn::IfThenElse(steep, ay, ax)));
  const V first = hn::IfThenElse(steep, hn::Sub(hn::Set(d, 0.5 * std::numbers::pi), r), r);
  const V upper = hn::Mul(
      hn::IfThenElse(hn::Lt(x, hn::Zero(d)), hn::Sub(hn::Set(d, std::numbers::pi), first), first),
      hn::Set(d, kDegPerRad));
  return hn::IfThenElse(hn::Lt(y, hn::Zero(d)), hn::Sub(hn::Set(d, 360.0), upper), upper);
}

// T = 1 − 0.17 cos(h̄′ − 30°) + 0.24 cos 2h̄′ + 0.32 cos(3h̄′ + 6°) − 0.20 cos(4h̄′ − 63°) from
// c = cos h̄′ and s = sin h̄′, through the multiple angles 2h̄′, 3h̄′, 4h̄′.
HWY_INLINE V t_term(D d, V c, V s) {
  const V two = hn::Set(d, 2.0), three = hn::Set(d, 3.0), four = hn::Set(d, 4.0);
  const V c2h = hn::Sub(hn::Mul(c, c), hn::Mul(s, s)), s2h = hn::Mul(hn::Mul(two, s), c);
  const V c3h = hn::Mul(c, hn::Sub(hn::Mul(hn::Mul(four, c), c), three));
  const V s3h = hn::Mul(s, hn::Sub(three, hn::Mul(hn::Mul(four, s), s)));
  const V c4h = hn::Sub(hn::Mul(c2h, c2h), hn::Mul(s2h, s2h)),
          s4h = hn::Mul(hn::Mul(two, s2h), c2h);
  const V t1 = hn::Add(hn::Mul(c, hn::Set(d, kCos30)), hn::Mul(s, hn::Set(d, kSin30)));
  const V t3 = hn::Sub(hn::Mul(c3h, hn::Set(d, kCos6)), hn::Mul(s3h, hn::Set(d, kSin6)));
  const V t4 = hn::Add(hn::Mul(c4h, hn::Set(d, kCos63)), hn::Mul(s4h, hn::Set(d, kSin63)));
  V t = hn::Sub(hn::Set(d, 1.0), hn::Mul(hn::Set(d, 0.17), t1));
  t = hn::Add(t, hn::Mul(hn::Set(d, 0.24), c2h));
  t = hn::Add(t, hn::Mul(hn::Set(d, 0.32), t3));
  return hn::Sub(t, hn::Mul(hn::Set(d, 0.20), t4));
}

// R_T = −sin(2Δθ)·R_C with Δθ = 30°·exp(−((h̄′ − 275°)/25°)²), h̄′ in [0°, 360°); zero for h̄′ in
// [0°, 134°), where Δθ is under 5e-13° (exp(−31.8)).
HWY_INLINE V rotation_term(D d, V c, V s, V cp_bar) {
  const M negligible = hn::And(hn::Ge(s, hn::Zero(d)), hn::Gt(c, hn::Set(d, kCos134)));
  const V q = hn::Mul(hn::Sub(atan2_deg(d, s, c), hn::Set(d, 275.0)), hn::Set(d, 1.0 / 25.0));
  const V d_theta = hn::Mul(hn::Set(d, 30.0), hn::Exp(d, hn::Neg(hn::Mul(q, q))));
  const V rc = hn::Mul(hn::Set(d, 2.0), chroma_weight(d, cp_bar));
  const V rt = hn::Neg(hn::Mul(hn::Sin(d, hn::Mul(d_theta, hn::Set(d, 2.0 / kDegPerRad))), rc));
  return hn::IfThenZeroElse(negligible, rt);
}

// ΔE00 from ΔL′, ΔC′, ΔH′, the means L̄′ and C̄′, and the T and R_T terms.
HWY_INLINE V weighted_difference(D d, V dl, V dc, V d_big_h, V l_bar, V cp_bar, V t, V rt) {
  const V one = hn::Set(d, 1.0);
  const V l50 = hn::Mul(hn::Sub(l_bar, hn::Set(d, 50.0)), hn::Sub(l_bar, hn::Set(d, 50.0)));
  const V sl = hn::Add(
      one, hn::Div(hn::Mul(hn::Set(d, 0.015), l50), hn::Sqrt(hn::Add(hn::Set(d, 20.0), l50))));
  const V sc = hn::Add(one, hn::Mul(hn::Set(d, 0.045), cp_bar));
  const V sh = hn::Add(one, hn::Mul(hn::Mul(hn::Set(d, 0.015), cp_bar), t));
  // One division for the three quotients ΔL′/S_L, ΔC′/S_C, ΔH′/S_H.
  const V sc_sh = hn::Mul(sc, sh), inv = hn::Div(one, hn::Mul(sl, sc_sh));
  const V tl = hn::Mul(dl, hn::Mul(sc_sh, inv)), tc = hn::Mul(dc, hn::Mul(hn::Mul(sl, sh), inv));
  const V th = hn::Mul(d_big_h, hn::Mul(hn::Mul(sl, sc), inv));
  const V e2 = hn::Add(hn::Add(hn::Add(hn::Mul(tl, tl), hn::Mul(tc, tc)), hn::Mul(th, th)),
                       hn::Mul(hn::Mul(rt, tc), th));
  return hn::IfThenElseZero(hn::Gt(e2, hn::Zero(d)), hn::Sqrt(e2));
}

// Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference formula: implementation notes", from
// the unit hue vectors u = (a′, b)/C′ instead of hue angles: one atan2 (the mean hue in degrees,
// for the Δθ term) instead of two, and the T term's four cosines and sin(Δh′/2) by vector algebra.
// ΔE00 of the lanes' pairs; `reference` marks achromatic colours (or chromas near underflow) and
// opposite hues (where the formula's hue conventions decide, not geometry), whose results the
// caller replaces with the reference's (the template ciede2000<double>).
HWY_INLINE V de2000_lanes(D d, const double* p1, const double* p2, M& reference) {
  V l1, a1, b1, l2, a2, b2;
  hn::LoadInterleaved3(d, p1, l1, a1, b1);
  hn::LoadInterleaved3(d, p2, l2, a2, b2);
  const V half = hn::Set(d, 0.5), one = hn::Set(d, 1.0);
  const V c1 = hn::Sqrt(hn::Add(hn::Mul(a1, a1), hn::Mul(b1, b1)));
  const V c2 = hn::Sqrt(hn::Add(hn::Mul(a2, a2), hn::Mul(b2, b2)));
  const V g1 =
      hn::Add(one, hn::Mul(half, hn::Sub(one, chroma_weight(d, hn::Mul(half, hn::Add(c1, c2))))));
  const V a1p = hn::Mul(g1, a1), a2p = hn::Mul(g1, a2);
  const V c1p = hn::Sqrt(hn::Add(hn::Mul(a1p, a1p), hn::Mul(b1, b1)));
  const V c2p = hn::Sqrt(hn::Add(hn::Mul(a2p, a2p), hn::Mul(b2, b2)));
  // Unit hue vectors u = (a′, b)/C′; ΔH′ = 2·sqrt(C′1·C′2)·sin(Δh′/2) from |u2 − u1| =
  // 2|sin(Δh′/2)|, signed as u1 × u2.
  const V cc = hn::Mul(c1p, c2p), inv_c1c2 = hn::Div(one, cc);
  const V inv_c1p = hn::Mul(c2p, inv_c1c2), inv_c2p = hn::Mul(c1p, inv_c1c2);
  const V u1x = hn::Mul(a1p, inv_c1p), u1y = hn::Mul(b1, inv_c1p);
  const V u2x = hn::Mul(a2p, inv_c2p), u2y = hn::Mul(b2, inv_c2p);
  const V dx = hn::Sub(u2x, u1x), dy = hn::Sub(u2y, u1y);
  const V d2 = hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy));
  const V cross = hn::Sub(hn::Mul(u1x, u2y), hn::Mul(u1y, u2x));
  const V mx = hn::Add(u1x, u2x), my = hn::Add(u1y, u2y);
  const V m2 = hn::Add(hn::Mul(mx, mx), hn::Mul(my, my));
  const M far = hn::Lt(m2, d2);
  // C′1·C′2 zero (an achromatic colour) or so small that its reciprocal overflows.
  const M achromatic = hn::Not(hn::Gt(cc, hn::Set(d, std::numeric_limits<double>::min())));
  reference =
      hn::Or(achromatic, hn::And(far, hn::Lt(hn::Abs(cross), hn::Set(d, kOppositeHueCross))));
  const V d_big_h = hn::CopySign(hn::Sqrt(hn::Mul(cc, d2)), cross);
  // The mean hue h̄′: the direction of u1 + u2, or, more than 90° apart, of u2 − u1 turned by ∓90°.
  const M ccw = hn::Gt(cross, hn::Zero(d));
  const V bx = hn::IfThenElse(far, hn::IfThenElse(ccw, dy, hn::Neg(dy)), mx);
  const V by = hn::IfThenElse(far, hn::IfThenElse(ccw, hn::Neg(dx), dx), my);
  const V inv_b = hn::Div(one, hn::Sqrt(hn::IfThenElse(far, d2, m2)));
  const V c = hn::Mul(bx, inv_b), s = hn::Mul(by, inv_b);
  const V cp_bar = hn::Mul(half, hn::Add(c1p, c2p));
  return weighted_difference(d, hn::Sub(l2, l1), hn::Sub(c2p, c1p), d_big_h,
                             hn::Mul(half, hn::Add(l1, l2)), cp_bar, t_term(d, c, s),
                             rotation_term(d, c, s, cp_bar));
}

// One vector of pairs from lab1, lab2 into out, the reference's values in the lanes it decides.
HWY_INLINE void de2000_vector(D d, const Lab* lab1, const Lab* lab2, double* out) {
  M reference;
  hn::StoreU(de2000_lanes(d, &lab1->L, &lab2->L, reference), d, out);
  if (hn::AllFalse(d, reference)) return;
  uint8_t bits[8] = {};
  hn::StoreMaskBits(d, reference, bits);
  for (size_t j = 0; j < hn::Lanes(d); ++j)
    if (bits[j / 8] >> (j % 8) & 1) out[j] = detail::ciede2000_reference(lab1[j], lab2[j]);
}

void ciede2000_batch_target(const Lab* lab1, const Lab* lab2, double* out, size_t n) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes) de2000_vector(d, lab1 + i, lab2 + i, out + i);
  if (i == n) return;
  // The tail, padded with its last pair so that every pair goes through the same lanes' formula.
  Lab t1[hn::MaxLanes(D())], t2[hn::MaxLanes(D())];
  double t_out[hn::MaxLanes(D())];
  for (size_t j = 0; j < lanes; ++j) {
    t1[j] = lab1[i + j < n ? i + j : n - 1];
    t2[j] = lab2[i + j < n ? i + j : n - 1];
  }
  de2000_vector(d, t1, t2, t_out);
  for (size_t j = 0; i + j < n; ++j) out[i + j] = t_out[j];
}

// ---- The fits' residuals, with their derivatives over the model colour's RGB ----

// Chromas under which the residuals' lanes leave a colour to the template, as they leave grey.
// There a hue turns by up to 1e-6 rad per 1e-12 change of a′ or b, and a fit whose colours stay
// that close to grey (a lossless dielectric of constant index, fitted with a grey model) follows
// its rounding: with the template's rounding it ends where the template's path ends.
constexpr double kNearGreyChroma = 1e-6;

// A vector of values with their derivatives over the model colour's R, G and B (forward mode).
struct DV {
  V v;
  V d[3];
};

HWY_INLINE DV dv(V v, V d0, V d1, V d2) {
  return DV{v, {d0, d1, d2}};
}
// v, with derivatives slope·x.d: the chain rule through a function of x alone.
HWY_INLINE DV chain(V v, V slope, const DV& x) {
  return dv(v, hn::Mul(slope, x.d[0]), hn::Mul(slope, x.d[1]), hn::Mul(slope, x.d[2]));
}
HWY_INLINE DV dv_add(const DV& x, const DV& y) {
  return dv(hn::Add(x.v, y.v), hn::Add(x.d[0], y.d[0]), hn::Add(x.d[1], y.d[1]),
            hn::Add(x.d[2], y.d[2]));
}
HWY_INLINE DV dv_add(const DV& x, V s) {
  return dv(hn::Add(x.v, s), x.d[0], x.d[1], x.d[2]);
}
HWY_INLINE DV dv_sub(const DV& x, const DV& y) {
  return dv(hn::Sub(x.v, y.v), hn::Sub(x.d[0], y.d[0]), hn::Sub(x.d[1], y.d[1]),
            hn::Sub(x.d[2], y.d[2]));
}
HWY_INLINE DV dv_scale(const DV& x, V s) {
  return chain(hn::Mul(x.v, s), s, x);
}
HWY_INLINE DV dv_mul(const DV& x, const DV& y) {
  const auto d = [&](int i) { return hn::Add(hn::Mul(y.v, x.d[i]), hn::Mul(x.v, y.d[i])); };
  return dv(hn::Mul(x.v, y.v), d(0), d(1), d(2));
}
HWY_INLINE DV dv_div(const DV& x, const DV& y) {
  const V q = hn::Div(x.v, y.v);
  const auto d = [&](int i) { return hn::Div(hn::Sub(x.d[i], hn::Mul(q, y.d[i])), y.v); };
  return dv(q, d(0), d(1), d(2));
}
HWY_INLINE DV dv_sqrt(const DV& x) {
  const V r = hn::Sqrt(x.v);
  return chain(r, hn::Div(hn::Set(D(), 0.5), r), x);
}
HWY_INLINE DV dv_select(M m, const DV& x, const DV& y) {
  return dv(hn::IfThenElse(m, x.v, y.v), hn::IfThenElse(m, x.d[0], y.d[0]),
            hn::IfThenElse(m, x.d[1], y.d[1]), hn::IfThenElse(m, x.d[2], y.d[2]));
}
HWY_INLINE DV dv_zero_where(M m, const DV& x) {
  return dv(hn::IfThenZeroElse(m, x.v), hn::IfThenZeroElse(m, x.d[0]),
            hn::IfThenZeroElse(m, x.d[1]), hn::IfThenZeroElse(m, x.d[2]));
}

// CIE 15:2004's f(t) of CIELAB: the cube root above (6/29)³, its linear toe below; dt is dt/dRGB.
// The cube root is exp(log(t)/3), refined by one Newton step to within about an ulp.
HWY_INLINE DV lab_f(D d, V t, const V (&dt)[3]) {
  constexpr double kDelta = 6.0 / 29.0;
  const V third = hn::Set(d, 1.0 / 3.0);
  const V r0 = hn::Exp(d, hn::Mul(hn::Log(d, t), third)), r0_sq = hn::Mul(r0, r0);
  const V root = hn::Sub(r0, hn::Div(hn::Mul(third, hn::Sub(hn::Mul(r0_sq, r0), t)), r0_sq));
  const M cube = hn::Gt(t, hn::Set(d, kDelta * kDelta * kDelta));
  const V toe_slope = hn::Set(d, 1.0 / (3.0 * kDelta * kDelta));
  const V f = hn::IfThenElse(cube, root, hn::Add(hn::Mul(t, toe_slope), hn::Set(d, 4.0 / 29.0)));
  const V slope = hn::IfThenElse(cube, hn::Div(third, hn::Mul(root, root)), toe_slope);
  return dv(f, hn::Mul(slope, dt[0]), hn::Mul(slope, dt[1]), hn::Mul(slope, dt[2]));
}

// chroma_weight above, sqrt(x⁷ / (x⁷ + 25⁷)), with its slope W·(7/2)·25⁷ / (x·(x⁷ + 25⁷)) (0 at x =
// 0).
HWY_INLINE DV chroma_weight(D d, const DV& x) {
  const V x7 = pow7(x.v), sum = hn::Add(x7, hn::Set(d, k25pow7));
  const V w = hn::Sqrt(hn::Div(x7, sum));
  const V slope = hn::Div(hn::Mul(w, hn::Set(d, 3.5 * k25pow7)), hn::Mul(x.v, sum));
  return chain(w, hn::IfThenZeroElse(hn::Eq(x.v, hn::Zero(d)), slope), x);
}

// t_term above with derivatives, from the mean hue's cosine c and sine s.
HWY_INLINE DV t_term(D d, const DV& c, const DV& s) {
  const auto k = [&](double x) { return hn::Set(d, x); };
  const DV c2h = dv_sub(dv_mul(c, c), dv_mul(s, s)), s2h = dv_scale(dv_mul(s, c), k(2.0));
  const DV c3h = dv_mul(c, dv_add(dv_scale(dv_mul(c, c), k(4.0)), k(-3.0)));
  const DV s3h = dv_mul(s, dv_add(dv_scale(dv_mul(s, s), k(-4.0)), k(3.0)));
  const DV c4h = dv_sub(dv_mul(c2h, c2h), dv_mul(s2h, s2h)),
           s4h = dv_scale(dv_mul(s2h, c2h), k(2.0));
  const DV t1 = dv_add(dv_scale(c, k(kCos30)), dv_scale(s, k(kSin30)));
  const DV t3 = dv_sub(dv_scale(c3h, k(kCos6)), dv_scale(s3h, k(kSin6)));
  const DV t4 = dv_add(dv_scale(c4h, k(kCos63)), dv_scale(s4h, k(kSin63)));
  DV t = dv_add(dv_scale(t1, k(-0.17)), k(1.0));
  t = dv_add(t, dv_scale(c2h, k(0.24)));
  t = dv_add(t, dv_scale(t3, k(0.32)));
  return dv_add(t, dv_scale(t4, k(-0.20)));
}

// rotation_term above with derivatives: atan2, exp and sin by the chain rule.
HWY_INLINE DV rotation_term(D d, const DV& c, const DV& s, const DV& cp_bar) {
  const auto k = [&](double x) { return hn::Set(d, x); };
  const M negligible = hn::And(hn::Ge(s.v, hn::Zero(d)), hn::Gt(c.v, k(kCos134)));
  // d atan2(s, c) = (c·ds − s·dc) / (c² + s²), here in degrees.
  const V norm = hn::Div(k(kDegPerRad), hn::Add(hn::Mul(c.v, c.v), hn::Mul(s.v, s.v)));
  const auto dh = [&](int i) {
    return hn::Mul(norm, hn::Sub(hn::Mul(c.v, s.d[i]), hn::Mul(s.v, c.d[i])));
  };
  const DV q =
      dv_scale(dv_add(dv(atan2_deg(d, s.v, c.v), dh(0), dh(1), dh(2)), k(-275.0)), k(1.0 / 25.0));
  const V e = hn::Mul(k(30.0), hn::Exp(d, hn::Neg(hn::Mul(q.v, q.v))));
  const DV d_theta = chain(e, hn::Mul(hn::Mul(k(-2.0), q.v), e), q);  // 30°·exp(−q²)
  const V angle = hn::Mul(d_theta.v, k(2.0 / kDegPerRad));
  const DV sin_2theta =
      chain(hn::Sin(d, angle), hn::Mul(hn::Cos(d, angle), k(2.0 / kDegPerRad)), d_theta);
  const DV rt = dv_mul(dv_scale(sin_2theta, k(-2.0)), chroma_weight(d, cp_bar));
  return dv_zero_where(negligible, rt);
}

// The model colour's CIELAB, xyz_to_lab(M·RGB), with derivatives over RGB.
HWY_INLINE void model_lab(D d, const LabConverter& to_lab, V r, V g, V b, DV& l2, DV& a2, DV& b2) {
  const double white[3] = {to_lab.white.X, to_lab.white.Y, to_lab.white.Z};
  DV f[3];
  for (int row = 0; row < 3; ++row) {
    const double* m = to_lab.rgb_to_xyz.m.data() + 3 * row;
    const V xyz = hn::Add(hn::Add(hn::Mul(hn::Set(d, m[0]), r), hn::Mul(hn::Set(d, m[1]), g)),
                          hn::Mul(hn::Set(d, m[2]), b));
    const V dt[3] = {hn::Set(d, m[0] / white[row]), hn::Set(d, m[1] / white[row]),
                     hn::Set(d, m[2] / white[row])};
    f[row] = lab_f(d, hn::Div(xyz, hn::Set(d, white[row])), dt);
  }
  l2 = dv_add(dv_scale(f[1], hn::Set(d, 116.0)), hn::Set(d, -16.0));
  a2 = dv_scale(dv_sub(f[0], f[1]), hn::Set(d, 500.0));
  b2 = dv_scale(dv_sub(f[1], f[2]), hn::Set(d, 200.0));
}

// The three residuals of ciede2000_residuals (lab.h) between the truth (l1, a1, b1) and the model
// colour to_lab(r, g, b), with their derivatives over r, g, b. The formula is de2000_lanes', except
// that within 90° ΔH′ = 2·sqrt(C′1·C′2)·sin(Δh′/2) is taken as 2·sqrt(C′1·C′2)·(u1 × u2)/|u1 + u2|,
// smooth where the hues meet, as a fit's residuals go to zero. `reference` marks the lanes
// de2000_lanes leaves to the reference.
HWY_INLINE void residual_lanes(D d, const LabConverter& to_lab, V l1, V a1, V b1, V r, V g, V b,
                               DV (&res)[3], M& reference) {
  const auto k = [&](double x) { return hn::Set(d, x); };
  DV l2, a2, b2;
  model_lab(d, to_lab, r, g, b, l2, a2, b2);
  const V c1 = hn::Sqrt(hn::Add(hn::Mul(a1, a1), hn::Mul(b1, b1)));
  const DV c2 = dv_sqrt(dv_add(dv_mul(a2, a2), dv_mul(b2, b2)));
  const DV g1 = dv_add(dv_scale(chroma_weight(d, dv_scale(dv_add(c2, c1), k(0.5))), k(-0.5)),
                       k(1.5));  // 1 + G
  const DV a1p = dv_scale(g1, a1), a2p = dv_mul(g1, a2);
  const DV c1p = dv_sqrt(dv_add(dv_mul(a1p, a1p), hn::Mul(b1, b1)));
  const DV c2p = dv_sqrt(dv_add(dv_mul(a2p, a2p), dv_mul(b2, b2)));
  const DV cc = dv_mul(c1p, c2p);
  const V b1_over_c1p = hn::Div(b1, c1p.v);
  const DV u1x = dv_div(a1p, c1p),
           u1y = chain(b1_over_c1p, hn::Neg(hn::Div(b1_over_c1p, c1p.v)), c1p);
  const DV u2x = dv_div(a2p, c2p), u2y = dv_div(b2, c2p);
  const DV dx = dv_sub(u2x, u1x), dy = dv_sub(u2y, u1y);
  const DV d2 = dv_add(dv_mul(dx, dx), dv_mul(dy, dy));
  const DV cross = dv_sub(dv_mul(u1x, u2y), dv_mul(u1y, u2x));
  const DV mx = dv_add(u1x, u2x), my = dv_add(u1y, u2y);
  const DV m2 = dv_add(dv_mul(mx, mx), dv_mul(my, my));
  const M far = hn::Lt(m2.v, d2.v);
  // Near grey (either chroma under kNearGreyChroma) the template decides, as it does for grey.
  const M near_grey = hn::Not(hn::Gt(hn::Min(c1p.v, c2p.v), k(kNearGreyChroma)));
  reference = hn::Or(near_grey, hn::And(far, hn::Lt(hn::Abs(cross.v), k(kOppositeHueCross))));
  const M ccw = hn::Gt(cross.v, hn::Zero(d));
  const DV near_h = dv_scale(dv_div(dv_mul(dv_sqrt(cc), cross), dv_sqrt(m2)), k(2.0));
  const DV far_abs = dv_sqrt(dv_mul(cc, d2));
  const DV d_big_h = dv_select(far, dv_select(ccw, far_abs, dv_scale(far_abs, k(-1.0))), near_h);
  // The mean hue's direction: u1 + u2, or, more than 90° apart, u2 − u1 turned by ∓90°.
  const DV neg_dx = dv_scale(dx, k(-1.0)), neg_dy = dv_scale(dy, k(-1.0));
  const DV bx = dv_select(far, dv_select(ccw, dy, neg_dy), mx);
  const DV by = dv_select(far, dv_select(ccw, neg_dx, dx), my);
  const DV len = dv_sqrt(dv_select(far, d2, m2));
  const DV c = dv_div(bx, len), s = dv_div(by, len);
  const DV cp_bar = dv_scale(dv_add(c1p, c2p), k(0.5));
  const DV t = t_term(d, c, s), rt = rotation_term(d, c, s, cp_bar);
  const DV l_off = dv_add(dv_scale(dv_add(l2, l1), k(0.5)), k(-50.0));  // L̄′ − 50
  const DV l50 = dv_mul(l_off, l_off);
  const DV sl = dv_add(dv_scale(dv_div(l50, dv_sqrt(dv_add(l50, k(20.0)))), k(0.015)), k(1.0));
  const DV sc = dv_add(dv_scale(cp_bar, k(0.045)), k(1.0));
  const DV sh = dv_add(dv_scale(dv_mul(cp_bar, t), k(0.015)), k(1.0));
  const DV tl = dv_div(dv_add(l2, hn::Neg(l1)), sl), tc = dv_div(dv_sub(c2p, c1p), sc),
           th = dv_div(d_big_h, sh);
  res[0] = tl;
  res[1] = dv_add(tc, dv_scale(dv_mul(rt, th), k(0.5)));
  res[2] = dv_mul(dv_sqrt(dv_add(dv_scale(dv_mul(rt, rt), k(-0.25)), k(1.0))), th);
}

// One vector of angles: residuals interleaved (3 per angle), derivatives into the 9 planes
// d_rgb[(3q + c)·stride + i]; the reference's values in the lanes it decides.
HWY_INLINE void residual_vector(D d, const LabConverter& to_lab, const Lab* truth, const Rgb* rgb,
                                double* residuals, double* d_rgb, size_t stride) {
  V l1, a1, b1, r, g, b;
  hn::LoadInterleaved3(d, &truth->L, l1, a1, b1);
  hn::LoadInterleaved3(d, &rgb->r, r, g, b);
  DV res[3];
  M reference;
  residual_lanes(d, to_lab, l1, a1, b1, r, g, b, res, reference);
  hn::StoreInterleaved3(res[0].v, res[1].v, res[2].v, d, residuals);
  for (int q = 0; q < 3; ++q)
    for (int c = 0; c < 3; ++c) hn::StoreU(res[q].d[c], d, d_rgb + (3 * q + c) * stride);
  if (hn::AllFalse(d, reference)) return;
  uint8_t bits[8] = {};
  hn::StoreMaskBits(d, reference, bits);
  for (size_t j = 0; j < hn::Lanes(d); ++j) {
    if (!(bits[j / 8] >> (j % 8) & 1)) continue;
    double jac[9];
    detail::ciede2000_residuals_reference(to_lab, truth[j], rgb[j], residuals + 3 * j, jac);
    for (int e = 0; e < 9; ++e) d_rgb[e * stride + j] = jac[e];
  }
}

void residuals_batch_target(const LabConverter& to_lab, const Lab* truth, const Rgb* rgb,
                            double* residuals, double* d_rgb, size_t n) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes)
    residual_vector(d, to_lab, truth + i, rgb + i, residuals + 3 * i, d_rgb + i, n);
  if (i == n) return;
  // The tail, padded with its last angle, through the same lanes' formula.
  Lab t_truth[hn::MaxLanes(D())];
  Rgb t_rgb[hn::MaxLanes(D())];
  double t_res[3 * hn::MaxLanes(D())], t_d[9 * hn::MaxLanes(D())];
  for (size_t j = 0; j < lanes; ++j) {
    t_truth[j] = truth[i + j < n ? i + j : n - 1];
    t_rgb[j] = rgb[i + j < n ? i + j : n - 1];
  }
  residual_vector(d, to_lab, t_truth, t_rgb, t_res, t_d, lanes);
  for (size_t j = 0; i + j < n; ++j) {
    for (int q = 0; q < 3; ++q) residuals[3 * (i + j) + q] = t_res[3 * j + q];
    for (int e = 0; e < 9; ++e) d_rgb[e * n + i + j] = t_d[e * lanes + j];
  }
}

}  // namespace fl::color::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fl::color {

static_assert(sizeof(Lab) == 3 * sizeof(double),
              "Lab arrays are loaded as interleaved L, a, b doubles");

static_assert(sizeof(Rgb) == 3 * sizeof(double),
              "Rgb arrays are loaded as interleaved r, g, b doubles");

double detail::ciede2000_reference(const Lab& lab1, const Lab& lab2) {
  return ciede2000<double>(lab1, lab2);
}

void detail::ciede2000_residuals_reference(const LabConverter& to_lab, const Lab& truth,
                                           const Rgb& rgb, double* residuals, double* d_rgb) {
  using RgbDual = Dual<3>;
  const RgbT<RgbDual> x{RgbDual::variable(rgb.r, 0), RgbDual::variable(rgb.g, 1),
                        RgbDual::variable(rgb.b, 2)};
  RgbDual r[3];
  ciede2000_residuals(LabT<RgbDual>{truth.L, truth.a, truth.b}, to_lab(x), r);
  for (int q = 0; q < 3; ++q) {
    residuals[q] = r[q].v;
    for (int c = 0; c < 3; ++c) d_rgb[3 * q + c] = r[q].d[c];
  }
}

namespace {

// The instruction sets this file is compiled for (foreach_target), best first, each with the CPU
// features Highway's own run-time check (hwy::SupportedTargets) requires of it. The choice is made
// here rather than by HWY_DYNAMIC_DISPATCH so that the program does not load libhwy, whose static
// initializer times the CPU's clock for about 12 ms at every start.
using BatchFn = void (*)(const Lab*, const Lab*, double*, size_t);
using ResidualsFn = void (*)(const LabConverter&, const Lab*, const Rgb*, double*, double*, size_t);
struct BatchTarget {
  const char* name;  // Highway's name of the target
  bool (*supported)();
  BatchFn fn;
  ResidualsFn residuals;
};
// The features of each target, as hwy::SupportedTargets checks them (targets.cc, Highway 1.0):
// each tier needs the one below it.
bool has_ssse3() {
  return __builtin_cpu_supports("sse2") && __builtin_cpu_supports("sse3") &&
         __builtin_cpu_supports("ssse3");
}
bool has_sse4() {
  return has_ssse3() && __builtin_cpu_supports("sse4.1") && __builtin_cpu_supports("sse4.2") &&
         __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("aes");
}
// F16C from CPUID leaf 1 (ECX bit 29): clang 14's __builtin_cpu_supports does not know "f16c".
bool has_f16c() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  return __get_cpuid(1, &eax, &ebx, &ecx, &edx) && (ecx & bit_F16C) != 0;
}
bool has_avx2() {
  return has_sse4() && __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") &&
         __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
         __builtin_cpu_supports("fma") && has_f16c();
}
bool has_avx3() {
  return has_avx2() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
         __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
}

const std::vector<BatchTarget>& batch_targets() {
  static const std::vector<BatchTarget> targets {
#if HWY_TARGETS & HWY_AVX3
    {"AVX3", has_avx3, &N_AVX3::ciede2000_batch_target, &N_AVX3::residuals_batch_target},
#endif
#if HWY_TARGETS & HWY_AVX2
        {"AVX2", has_avx2, &N_AVX2::ciede2000_batch_target, &N_AVX2::residuals_batch_target},
#endif
#if HWY_TARGETS & HWY_SSE4
        {"SSE4", has_sse4, &N_SSE4::ciede2000_batch_target, &N_SSE4::residuals_batch_target},
#endif
#if HWY_TARGETS & HWY_SSSE3
        {"SSSE3", has_ssse3, &N_SSSE3::ciede2000_batch_target, &N_SSSE3::residuals_batch_target},
#endif
#if HWY_TARGETS & HWY_EMU128
        {"EMU128", [] { return true; }, &N_EMU128::ciede2000_batch_target,
         &N_EMU128::residuals_batch_target},
#endif
#if HWY_TARGETS & HWY_SCALAR
        {"SCALAR", [] { return true; }, &N_SCALAR::ciede2000_batch_target,
         &N_SCALAR::residuals_batch_target},
#endif
#if !(HWY_TARGETS & (HWY_AVX3 | HWY_AVX2 | HWY_SSE4 | HWY_SSSE3 | HWY_EMU128 | HWY_SCALAR))
        // None of the above built (-march flags of a newer CPU): the target those flags select,
        // which any CPU the program runs on has.
        {"STATIC", [] { return true; }, &HWY_STATIC_DISPATCH(ciede2000_batch_target),
         &HWY_STATIC_DISPATCH(residuals_batch_target)},
#endif
  };
  return targets;
}

// The supported targets, best first.
const std::vector<const BatchTarget*>& supported_targets() {
  static const std::vector<const BatchTarget*> supported = [] {
    std::vector<const BatchTarget*> out;
    for (const auto& t : batch_targets())
      if (t.supported()) out.push_back(&t);
    return out;
  }();
  return supported;
}

// A supported target by Highway's name; `caller` names the function in the error.
const BatchTarget& target_named(const std::string& name, const char* caller) {
  for (const auto* t : supported_targets())
    if (name == t->name) return *t;
  throw std::invalid_argument(std::string(caller) + ": no instruction set " + name +
                              " on this CPU");
}

void check_lengths(std::span<const Lab> lab1, std::span<const Lab> lab2, std::span<double> out) {
  if (lab1.size() != lab2.size() || lab1.size() != out.size())
    throw std::invalid_argument("ciede2000_batch: lab1, lab2 and out differ in length");
}

void check_lengths(std::span<const Lab> truth, std::span<const Rgb> rgb,
                   std::span<double> residuals, std::span<double> d_rgb) {
  if (truth.size() != rgb.size() || residuals.size() != 3 * rgb.size() ||
      d_rgb.size() != 9 * rgb.size())
    throw std::invalid_argument(
        "ciede2000_residuals_batch: truth, rgb, residuals and d_rgb do not match in length");
}

}  // namespace

void ciede2000_batch(std::span<const Lab> lab1, std::span<const Lab> lab2, std::span<double> out) {
  check_lengths(lab1, lab2, out);
  if (out.empty()) return;
  supported_targets().front()->fn(lab1.data(), lab2.data(), out.data(), out.size());
}

void ciede2000_residuals_batch(const LabConverter& to_lab, std::span<const Lab> truth,
                               std::span<const Rgb> rgb, std::span<double> residuals,
                               std::span<double> d_rgb) {
  check_lengths(truth, rgb, residuals, d_rgb);
  if (rgb.empty()) return;
  supported_targets().front()->residuals(to_lab, truth.data(), rgb.data(), residuals.data(),
                                         d_rgb.data(), rgb.size());
}

void ciede2000_residuals_batch_on(const std::string& target, const LabConverter& to_lab,
                                  std::span<const Lab> truth, std::span<const Rgb> rgb,
                                  std::span<double> residuals, std::span<double> d_rgb) {
  check_lengths(truth, rgb, residuals, d_rgb);
  const auto& t = target_named(target, "ciede2000_residuals_batch_on");
  if (!rgb.empty())
    t.residuals(to_lab, truth.data(), rgb.data(), residuals.data(), d_rgb.data(), rgb.size());
}

std::vector<std::string> ciede2000_batch_targets() {
  std::vector<std::string> names;
  for (const auto* t : supported_targets()) names.emplace_back(t->name);
  return names;
}

void ciede2000_batch_on(const std::string& target, std::span<const Lab> lab1,
                        std::span<const Lab> lab2, std::span<double> out) {
  check_lengths(lab1, lab2, out);
  const auto& t = target_named(target, "ciede2000_batch_on");
  if (!out.empty()) t.fn(lab1.data(), lab2.data(), out.data(), out.size());
}

}  // namespace fl::color
#endif  // HWY_ONCE
