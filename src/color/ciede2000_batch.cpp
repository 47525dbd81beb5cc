// Highway (hwy/foreach_target.h) compiles this file once per x86 instruction set and
// batch_targets() below picks the best one the CPU has; Highway's headers stay in this file.
#include "color/ciede2000_batch.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "color/ciede2000_constants.h"
#include "color/lab.h"

namespace fl::color::detail {
// The template ciede2000<double>, compiled for the baseline instruction set, for the lanes the
// vector formula leaves to it.
double ciede2000_reference(const Lab& lab1, const Lab& lab2);
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

using namespace detail;  // the formula's constants (ciede2000_constants.h), kPi, kDegPerRad

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
  const V first = hn::IfThenElse(steep, hn::Sub(hn::Set(d, 0.5 * kPi), r), r);
  const V upper = hn::Mul(hn::IfThenElse(hn::Lt(x, hn::Zero(d)), hn::Sub(hn::Set(d, kPi), first), first),
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
  const V c4h = hn::Sub(hn::Mul(c2h, c2h), hn::Mul(s2h, s2h)), s4h = hn::Mul(hn::Mul(two, s2h), c2h);
  const V t1 = hn::Add(hn::Mul(c, hn::Set(d, kCos30)), hn::Mul(s, hn::Set(d, kSin30)));
  const V t3 = hn::Sub(hn::Mul(c3h, hn::Set(d, kCos6)), hn::Mul(s3h, hn::Set(d, kSin6)));
  const V t4 = hn::Add(hn::Mul(c4h, hn::Set(d, kCos63)), hn::Mul(s4h, hn::Set(d, kSin63)));
  V t = hn::Sub(hn::Set(d, 1.0), hn::Mul(hn::Set(d, 0.17), t1));
  t = hn::Add(t, hn::Mul(hn::Set(d, 0.24), c2h));
  t = hn::Add(t, hn::Mul(hn::Set(d, 0.32), t3));
  return hn::Sub(t, hn::Mul(hn::Set(d, 0.20), t4));
}

// R_T = −sin(2Δθ)·R_C with Δθ = 30°·exp(−((h̄′ − 275°)/25°)²), h̄′ in [0°, 360°); zero for h̄′ in
// [0°, 134°), where Δθ is under 5e-13° (exp(−31.8)), as in ciede2000_fast.
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
  const V sl = hn::Add(one, hn::Div(hn::Mul(hn::Set(d, 0.015), l50), hn::Sqrt(hn::Add(hn::Set(d, 20.0), l50))));
  const V sc = hn::Add(one, hn::Mul(hn::Set(d, 0.045), cp_bar));
  const V sh = hn::Add(one, hn::Mul(hn::Mul(hn::Set(d, 0.015), cp_bar), t));
  // One division for the three quotients ΔL′/S_L, ΔC′/S_C, ΔH′/S_H.
  const V sc_sh = hn::Mul(sc, sh), inv = hn::Div(one, hn::Mul(sl, sc_sh));
  const V tl = hn::Mul(dl, hn::Mul(sc_sh, inv)), tc = hn::Mul(dc, hn::Mul(hn::Mul(sl, sh), inv));
  const V th = hn::Mul(d_big_h, hn::Mul(hn::Mul(sl, sc), inv));
  const V e2 = hn::Add(hn::Add(hn::Add(hn::Mul(tl, tl), hn::Mul(tc, tc)), hn::Mul(th, th)), hn::Mul(hn::Mul(rt, tc), th));
  return hn::IfThenElseZero(hn::Gt(e2, hn::Zero(d)), hn::Sqrt(e2));
}

// Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference formula: implementation notes", with
// ciede2000_fast's hue vectors: ΔE00 of the lanes' pairs; `reference` marks achromatic colours (or chromas near underflow) and
// opposite hues (see ciede2000_fast), whose results the caller replaces with the reference's.
HWY_INLINE V de2000_lanes(D d, const double* p1, const double* p2, M& reference) {
  V l1, a1, b1, l2, a2, b2;
  hn::LoadInterleaved3(d, p1, l1, a1, b1);
  hn::LoadInterleaved3(d, p2, l2, a2, b2);
  const V half = hn::Set(d, 0.5), one = hn::Set(d, 1.0);
  const V c1 = hn::Sqrt(hn::Add(hn::Mul(a1, a1), hn::Mul(b1, b1)));
  const V c2 = hn::Sqrt(hn::Add(hn::Mul(a2, a2), hn::Mul(b2, b2)));
  const V g1 = hn::Add(one, hn::Mul(half, hn::Sub(one, chroma_weight(d, hn::Mul(half, hn::Add(c1, c2))))));
  const V a1p = hn::Mul(g1, a1), a2p = hn::Mul(g1, a2);
  const V c1p = hn::Sqrt(hn::Add(hn::Mul(a1p, a1p), hn::Mul(b1, b1)));
  const V c2p = hn::Sqrt(hn::Add(hn::Mul(a2p, a2p), hn::Mul(b2, b2)));
  // Unit hue vectors u = (a′, b)/C′; ΔH′ = 2·sqrt(C′1·C′2)·sin(Δh′/2) from |u2 − u1| = 2|sin(Δh′/2)|,
  // signed as u1 × u2.
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
  reference = hn::Or(achromatic, hn::And(far, hn::Lt(hn::Abs(cross), hn::Set(d, kOppositeHueCross))));
  const V d_big_h = hn::CopySign(hn::Sqrt(hn::Mul(cc, d2)), cross);
  // The mean hue h̄′: the direction of u1 + u2, or, more than 90° apart, of u2 − u1 turned by ∓90°.
  const M ccw = hn::Gt(cross, hn::Zero(d));
  const V bx = hn::IfThenElse(far, hn::IfThenElse(ccw, dy, hn::Neg(dy)), mx);
  const V by = hn::IfThenElse(far, hn::IfThenElse(ccw, hn::Neg(dx), dx), my);
  const V inv_b = hn::Div(one, hn::Sqrt(hn::IfThenElse(far, d2, m2)));
  const V c = hn::Mul(bx, inv_b), s = hn::Mul(by, inv_b);
  const V cp_bar = hn::Mul(half, hn::Add(c1p, c2p));
  return weighted_difference(d, hn::Sub(l2, l1), hn::Sub(c2p, c1p), d_big_h, hn::Mul(half, hn::Add(l1, l2)), cp_bar,
                             t_term(d, c, s), rotation_term(d, c, s, cp_bar));
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

}  // namespace fl::color::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fl::color {

static_assert(sizeof(Lab) == 3 * sizeof(double), "Lab arrays are loaded as interleaved L, a, b doubles");

double detail::ciede2000_reference(const Lab& lab1, const Lab& lab2) { return ciede2000<double>(lab1, lab2); }

namespace {

// The instruction sets this file is compiled for (foreach_target), best first, each with the CPU
// features Highway's own run-time check (hwy::SupportedTargets) requires of it. The choice is made
// here rather than by HWY_DYNAMIC_DISPATCH so that the program does not load libhwy, whose static
// initializer times the CPU's clock for about 12 ms at every start.
using BatchFn = void (*)(const Lab*, const Lab*, double*, size_t);
struct BatchTarget {
  const char* name;  // Highway's name of the target
  bool (*supported)();
  BatchFn fn;
};
// The features of each target, as hwy::SupportedTargets checks them (targets.cc, Highway 1.0):
// each tier needs the one below it.
bool has_ssse3() { return __builtin_cpu_supports("sse2") && __builtin_cpu_supports("sse3") && __builtin_cpu_supports("ssse3"); }
bool has_sse4() {
  return has_ssse3() && __builtin_cpu_supports("sse4.1") && __builtin_cpu_supports("sse4.2") &&
         __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("aes");
}
bool has_avx2() {
  return has_sse4() && __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") &&
         __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("fma") &&
         __builtin_cpu_supports("f16c");
}
bool has_avx3() {
  return has_avx2() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
         __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
}

const std::vector<BatchTarget>& batch_targets() {
  static const std::vector<BatchTarget> targets{
#if HWY_TARGETS & HWY_AVX3
      {"AVX3", has_avx3, &N_AVX3::ciede2000_batch_target},
#endif
#if HWY_TARGETS & HWY_AVX2
      {"AVX2", has_avx2, &N_AVX2::ciede2000_batch_target},
#endif
#if HWY_TARGETS & HWY_SSE4
      {"SSE4", has_sse4, &N_SSE4::ciede2000_batch_target},
#endif
#if HWY_TARGETS & HWY_SSSE3
      {"SSSE3", has_ssse3, &N_SSSE3::ciede2000_batch_target},
#endif
#if HWY_TARGETS & HWY_EMU128
      {"EMU128", [] { return true; }, &N_EMU128::ciede2000_batch_target},
#endif
#if HWY_TARGETS & HWY_SCALAR
      {"SCALAR", [] { return true; }, &N_SCALAR::ciede2000_batch_target},
#endif
#if !(HWY_TARGETS & (HWY_AVX3 | HWY_AVX2 | HWY_SSE4 | HWY_SSSE3 | HWY_EMU128 | HWY_SCALAR))
      // None of the above built (-march flags of a newer CPU): the target those flags select, which
      // any CPU the program runs on has.
      {"STATIC", [] { return true; }, &HWY_STATIC_DISPATCH(ciede2000_batch_target)},
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

void check_lengths(std::span<const Lab> lab1, std::span<const Lab> lab2, std::span<double> out) {
  if (lab1.size() != lab2.size() || lab1.size() != out.size())
    throw std::invalid_argument("ciede2000_batch: lab1, lab2 and out differ in length");
}

}  // namespace

void ciede2000_batch(std::span<const Lab> lab1, std::span<const Lab> lab2, std::span<double> out) {
  check_lengths(lab1, lab2, out);
  if (out.empty()) return;
  supported_targets().front()->fn(lab1.data(), lab2.data(), out.data(), out.size());
}

std::vector<std::string> ciede2000_batch_targets() {
  std::vector<std::string> names;
  for (const auto* t : supported_targets()) names.emplace_back(t->name);
  return names;
}

void ciede2000_batch_on(const std::string& target, std::span<const Lab> lab1, std::span<const Lab> lab2,
                        std::span<double> out) {
  check_lengths(lab1, lab2, out);
  for (const auto* t : supported_targets()) {
    if (target != t->name) continue;
    if (!out.empty()) t->fn(lab1.data(), lab2.data(), out.data(), out.size());
    return;
  }
  throw std::invalid_argument("ciede2000_batch_on: no instruction set " + target + " on this CPU");
}

}  // namespace fl::color
#endif  // HWY_ONCE
