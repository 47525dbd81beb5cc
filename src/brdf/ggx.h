#pragma once
// Isotropic GGX microfacet kernels (the specular lobe of Filament's standard model) and the
// low-discrepancy points used to integrate them. Pure functions; no third-party dependencies.
//
// Frame: the surface normal is n = (0, 0, 1); an isotropic lobe is evaluated with the view
// vector in the xz-plane, v = (sinθ_v, 0, cosθ_v). alpha is the GGX width α =
// perceptual_roughness².
#include <cmath>
#include <cstdint>
#include <numbers>

namespace fl::brdf {

template <class T>
struct Vec3T {
  T x{}, y{}, z{};
};
using Vec3 = Vec3T<double>;

template <class T>
T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
Vec3T<T> normalize(const Vec3T<T>& a) {
  using std::sqrt;
  const T inv_len = 1.0 / sqrt(dot(a, a));
  return {a.x * inv_len, a.y * inv_len, a.z * inv_len};
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// max(0, x) for a number x as glibc's fmax(0.0, x) gives it (−0 stays −0), without the library
// call.
inline double max0(double x) {
  return x < 0.0 ? 0.0 : x;
}

// The view vector of an isotropic lobe at cosθ_v = nov (clamped to [0, 1]).
inline Vec3 view_from_nov(double nov) {
  const double c = std::fmin(1.0, std::fmax(0.0, nov));
  return {std::sqrt(std::fmax(0.0, 1.0 - c * c)), 0.0, c};
}

// Filament §4.4.1 (Walter et al. 2007): GGX NDF D(h) = α² / (π ((n·h)²(α² − 1) + 1)²).
// The 1/π makes the projected microfacet area integrate to one: ∫ D(h) (n·h) dω_h = 1.
template <class T>
T ggx_ndf(T noh, T alpha) {
  const T a2 = alpha * alpha;
  const T f = noh * noh * (a2 - 1.0) + 1.0;
  return a2 / (std::numbers::pi * f * f);
}

// Filament §4.4.2 (Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 99):
// height-correlated Smith visibility V = G₂ / (4 (n·v)(n·l))
//   = 0.5 / ((n·l) √((n·v)²(1 − α²) + α²) + (n·v) √((n·l)²(1 − α²) + α²)).
template <class T>
T smith_ggx_correlated_visibility(T nov, T nol, T alpha) {
  using std::sqrt;
  const T a2 = alpha * alpha;
  const T ggx_v = nol * sqrt(nov * nov * (1.0 - a2) + a2);
  const T ggx_l = nov * sqrt(nol * nol * (1.0 - a2) + a2);
  return 0.5 / (ggx_v + ggx_l);
}

// Heitz 2014, eq. 43 for GGX: Smith masking of one direction, G₁ = 2 (n·v) / ((n·v) + √(α² + (1 −
// α²)(n·v)²)).
template <class T>
T smith_ggx_g1(T nov, T alpha) {
  using std::sqrt;
  const T a2 = alpha * alpha;
  return 2.0 * nov / (nov + sqrt(a2 + (1.0 - a2) * nov * nov));
}

// Filament §4.4 (Cook-Torrance without Fresnel): the specular lobe times the cosine,
// ρ(v, l)·(n·l) = D(h) V(v, l) (n·l); zero when l is below the horizon.
// The value is computed first and then selected, so a loop over directions has no branch.
inline double ggx_lobe_cos(const Vec3& v, const Vec3& l, double alpha) {
  const double nov = v.z, nol = l.z;
  const Vec3 h = normalize(Vec3{v.x + l.x, v.y + l.y, v.z + l.z});
  const double value = ggx_ndf(h.z, alpha) * smith_ggx_correlated_visibility(nov, nol, alpha) * nol;
  const bool above = nol > 0.0 && nov > 0.0;
  return above ? value : 0.0;
}

// Heitz 2018, listing 1: the uniform point (√u1 cos 2πu2, √u1 sin 2πu2) of the unit disk that the
// visible-normal sampler warps, with the half-chord √(1 − p1²) at p1 that the warp scales; neither
// depends on the view, so a point set can be shared by every view.
struct DiskPoint {
  double p1 = 0, p2 = 0, chord = 1;
};
inline DiskPoint disk_point(double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = 2.0 * std::numbers::pi * u2;
  const double p1 = r * std::cos(phi);
  return {p1, r * std::sin(phi), std::sqrt(max0(1.0 - p1 * p1))};
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)), listing 1 with
// α_x = α_y = α: a microfacet normal h drawn from the visible-normal distribution
// D_v(h) = G₁(v) max(0, v·h) D(h) / (n·v), from two uniform numbers u1, u2 ∈ [0, 1).
// The view's part (the stretched view vh and the frame t1, t2 of its hemisphere) is computed once
// per view by GgxVndfSampler; sample_ggx_vndf is one draw of it.
struct GgxVndfSampler {
  Vec3 vh, t1, t2;
  double alpha = 1, s = 1;
  GgxVndfSampler(const Vec3& v, double alpha_) : alpha(alpha_) {
    vh = normalize(Vec3{alpha * v.x, alpha * v.y, v.z});
    const double len2 = vh.x * vh.x + vh.y * vh.y;
    t1 = len2 > 0.0 ? Vec3{-vh.y / std::sqrt(len2), vh.x / std::sqrt(len2), 0.0}
                    : Vec3{1.0, 0.0, 0.0};
    t2 = cross(vh, t1);
    s = 0.5 * (1.0 + vh.z);
  }
  Vec3 operator()(double u1, double u2) const { return (*this)(disk_point(u1, u2)); }
  // The same draw from the view-independent point of the unit disk that (u1, u2) maps to.
  Vec3 operator()(const DiskPoint& d) const {
    const double p1 = d.p1;
    const double p2 = (1.0 - s) * d.chord + s * d.p2;
    const double p3 = std::sqrt(max0(1.0 - p1 * p1 - p2 * p2));
    const Vec3 nh{p1 * t1.x + p2 * t2.x + p3 * vh.x, p1 * t1.y + p2 * t2.y + p3 * vh.y,
                  p1 * t1.z + p2 * t2.z + p3 * vh.z};
    return normalize(Vec3{alpha * nh.x, alpha * nh.y, max0(nh.z)});
  }
};
inline Vec3 sample_ggx_vndf(const Vec3& v, double alpha, double u1, double u2) {
  return GgxVndfSampler(v, alpha)(u1, u2);
}

// The mirror direction l = 2(v·h)h − v.
inline Vec3 reflect(const Vec3& v, const Vec3& h) {
  const double d = 2.0 * dot(v, h);
  return {d * h.x - v.x, d * h.y - v.y, d * h.z - v.z};
}

// Heitz 2018, eq. 17: the density of l = reflect(v, h) when h is drawn by sample_ggx_vndf,
// p(l) = D_v(h) / (4 (v·h)) = G₁(v) D(h) / (4 (n·v)); 4(v·h) is the Jacobian |dω_l/dω_h|.
inline double ggx_vndf_reflection_pdf(double nov, double noh, double alpha) {
  return smith_ggx_g1(nov, alpha) * ggx_ndf(noh, alpha) / (4.0 * nov);
}

// Heitz 2018, eq. 17 applied to the lobe: with l from VNDF sampling the estimator of
// ∫ D V (n·l) dω_l is D V (n·l) / p(l) = 4 V (n·v)(n·l) / G₁(v) = G₂(v, l) / G₁(v), and 0 below the
// horizon.
inline double ggx_vndf_weight(double nov, double nol, double alpha) {
  if (nol <= 0.0) return 0.0;
  return 4.0 * smith_ggx_correlated_visibility(nov, nol, alpha) * nov * nol /
         smith_ggx_g1(nov, alpha);
}

// ggx_vndf_weight, ggx_vndf_reflection_pdf and ggx_lobe_cos at one view, with the view's factors
// (its Smith term √((n·v)²(1 − α²) + α²) and G₁(v)) computed once; the same operations in the same
// order, so the same values.
struct GgxVndfWeight {
  double nov = 1, alpha = 1, a2 = 1, view_root = 1, g1 = 1;
  GgxVndfWeight(double nov_, double alpha_)
      : nov(nov_),
        alpha(alpha_),
        a2(alpha * alpha),
        view_root(std::sqrt(nov * nov * (1.0 - a2) + a2)),
        g1(smith_ggx_g1(nov, alpha)) {}
  // smith_ggx_correlated_visibility(nov, nol, alpha)
  double visibility(double nol) const {
    return 0.5 / (nol * view_root + nov * std::sqrt(nol * nol * (1.0 - a2) + a2));
  }
  // ggx_vndf_weight(nov, nol, alpha)
  double operator()(double nol) const {
    return nol <= 0.0 ? 0.0 : 4.0 * visibility(nol) * nov * nol / g1;
  }
  // ggx_vndf_reflection_pdf(nov, noh, alpha)
  double reflection_pdf(double noh) const { return g1 * ggx_ndf(noh, alpha) / (4.0 * nov); }
  // ggx_lobe_cos(v, l, alpha) for l at n·l = nol whose half vector with v is at n·h = noh
  double lobe_cos(double nol, double noh) const {
    const double value = ggx_ndf(noh, alpha) * visibility(nol) * nol;
    return nol > 0.0 && nov > 0.0 ? value : 0.0;
  }
};

// Van der Corput radical inverse in base 2 (Hammersley 1964), by bit reversal.
inline double radical_inverse_base2(std::uint32_t bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return static_cast<double>(bits) * 0x1p-32;  // 2⁻³²: the 32 reversed bits as a fraction in [0, 1)
}

struct Point2 {
  double u1 = 0, u2 = 0;
};

// Hammersley 1964 (as in Filament's IBL code, after Dammertz 2012): point i of n is
// (radical_inverse(i), (i + ½)/n). Filament uses i/n; the half offset centres each stratum.
inline Point2 hammersley(std::uint32_t i, std::uint32_t n) {
  return {radical_inverse_base2(i), (static_cast<double>(i) + 0.5) / static_cast<double>(n)};
}

}  // namespace fl::brdf
