// The LTC lobe (Heitz, Dupuy, Hill & Neubelt 2016: its frame, matrix, density and sampling) and the
// directions a cell is integrated over: the point sets, the GGX and LTC halves of a direction set,
// the held-out L3 error of an LTC and the fit's samples (LtcProblem). One file, so that the
// direction loops inline the lobe's functions.
#include "analysis/ltc/ltc_samples.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/codegen.h"

namespace fl::analysis {

LtcFrame ltc_frame_from_average_direction(const brdf::Vec3& average_dir) {
  const brdf::Vec3 z = brdf::normalize(brdf::Vec3{average_dir.x, 0.0, average_dir.z});
  return {{z.z, 0.0, -z.x}, {0.0, 1.0, 0.0}, z};
}

LtcMatrix ltc_matrix(const LtcFrame& f, const LtcParams& p) {
  // [X Y Z] · [[m11, 0, m13], [0, m22, 0], [m31, 0, 1]]: columns m11·X + m31·Z, m22·Y, m13·X + Z.
  const brdf::Vec3 c0{p.m11 * f.x.x + p.m31 * f.z.x, p.m11 * f.x.y + p.m31 * f.z.y,
                      p.m11 * f.x.z + p.m31 * f.z.z};
  const brdf::Vec3 c1{p.m22 * f.y.x, p.m22 * f.y.y, p.m22 * f.y.z};
  const brdf::Vec3 c2{p.m13 * f.x.x + f.z.x, p.m13 * f.x.y + f.z.y, p.m13 * f.x.z + f.z.z};
  return {{c0.x, c1.x, c2.x, c0.y, c1.y, c2.y, c0.z, c1.z, c2.z}};
}

double ltc_density(const LtcParams& p, double x, double y, double z) {
  const double beta = p.m11 - p.m13 * p.m31;
  const double ox = (x - p.m13 * z) / beta, oy = y / p.m22, oz = (p.m11 * z - p.m31 * x) / beta;
  if (oz <= 0.0) return 0.0;
  const double len2 = ox * ox + oy * oy + oz * oz;
  return oz / (std::numbers::pi * p.m22 * beta * len2 * len2);
}

LtcMatrix inverse(const LtcMatrix& a) {
  const auto& m = a.m;
  const double c00 = m[4] * m[8] - m[5] * m[7];
  const double c01 = m[5] * m[6] - m[3] * m[8];
  const double c02 = m[3] * m[7] - m[4] * m[6];
  const double inv_det = 1.0 / (m[0] * c00 + m[1] * c01 + m[2] * c02);
  return {{c00 * inv_det, (m[2] * m[7] - m[1] * m[8]) * inv_det,
           (m[1] * m[5] - m[2] * m[4]) * inv_det, c01 * inv_det,
           (m[0] * m[8] - m[2] * m[6]) * inv_det, (m[2] * m[3] - m[0] * m[5]) * inv_det,
           c02 * inv_det, (m[1] * m[6] - m[0] * m[7]) * inv_det,
           (m[0] * m[4] - m[1] * m[3]) * inv_det}};
}

LtcLobe ltc_lobe(const LtcMatrix& m) {
  LtcLobe lobe{m, inverse(m), 1.0};
  const auto& a = lobe.m_inv.m;
  lobe.abs_det_m_inv =
      std::abs(a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
               a[2] * (a[3] * a[7] - a[4] * a[6]));
  return lobe;
}

double ltc_lobe_density(const LtcLobe& lobe, const brdf::Vec3& w) {
  const auto& a = lobe.m_inv.m;
  const double ox = a[0] * w.x + a[1] * w.y + a[2] * w.z;
  const double oy = a[3] * w.x + a[4] * w.y + a[5] * w.z;
  const double oz = a[6] * w.x + a[7] * w.y + a[8] * w.z;
  const double len2 = ox * ox + oy * oy + oz * oz;
  const double density = oz * lobe.abs_det_m_inv / (std::numbers::pi * len2 * len2);
  return oz <= 0.0 ? 0.0 : density;
}

namespace {

// Heitz et al. 2016's D_o = max(0, z_o)/π drawn by inversion: the direction of (u1, u2) with
// cos θ_o = √u1, φ_o = 2π u2.
brdf::Vec3 cosine_direction(double u1, double u2) {
  const double cos_t = std::sqrt(u1), sin_t = std::sqrt(std::max(0.0, 1.0 - u1));
  const double phi = 2.0 * std::numbers::pi * u2;
  return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
}

// Heitz et al. 2016, eq. 1: the direction ω = M ω_o / ‖M ω_o‖ of the LTC for ω_o drawn from D_o.
brdf::Vec3 ltc_direction(const LtcLobe& lobe, const brdf::Vec3& o) {
  const auto& m = lobe.m.m;
  return brdf::normalize(brdf::Vec3{m[0] * o.x + m[1] * o.y + m[2] * o.z,
                                    m[3] * o.x + m[4] * o.y + m[5] * o.z,
                                    m[6] * o.x + m[7] * o.y + m[8] * o.z});
}

}  // namespace

brdf::Vec3 sample_ltc_lobe(const LtcLobe& lobe, double u1, double u2) {
  return ltc_direction(lobe, cosine_direction(u1, u2));
}

// The value is computed first and then selected, so a loop over directions has no branch.
double ggx_vndf_direction_pdf(const brdf::Vec3& v, const brdf::Vec3& l, double alpha) {
  const brdf::Vec3 sum{v.x + l.x, v.y + l.y, v.z + l.z};
  const double len2 = brdf::dot(sum, sum);
  const brdf::Vec3 h = brdf::normalize(sum);
  const double pdf = brdf::ggx_vndf_reflection_pdf(v.z, h.z, alpha);
  const bool valid = v.z > 0.0 && len2 > 0.0 && h.z > 0.0;
  return valid ? pdf : 0.0;
}

std::vector<brdf::Point2> stratified_midpoints(int k) {
  std::vector<brdf::Point2> pts;
  pts.reserve(static_cast<size_t>(k) * k);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) pts.push_back({(i + 0.5) / k, (j + 0.5) / k});
  return pts;
}

std::vector<brdf::Point2> hammersley_points(int n) {
  std::vector<brdf::Point2> pts;
  pts.reserve(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k)
    pts.push_back(brdf::hammersley(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(n)));
  return pts;
}

LtcPointSet point_set(const std::vector<brdf::Point2>& pts) {
  LtcPointSet set;
  for (const auto& u : pts) {
    set.disk.push_back(brdf::disk_point(u.u1, u.u2));
    set.cosine.push_back(cosine_direction(u.u1, u.u2));
  }
  return set;
}

// The GGX half: l = reflect(v, h) for h drawn from the visible normals at each disk point.
FL_FLATTEN Directions ggx_half(const brdf::Vec3& view, double alpha,
                               const std::vector<brdf::DiskPoint>& disk) {
  Directions d(disk.size());
  const brdf::Vec3 v = view;
  const brdf::GgxVndfSampler vndf(v, alpha);
#pragma GCC ivdep
  for (size_t k = 0; k < disk.size(); ++k) {
    const brdf::Vec3 l = brdf::reflect(v, vndf(disk[k]));
    d.x[k] = l.x, d.y[k] = l.y, d.z[k] = l.z;
    d.target[k] = brdf::ggx_lobe_cos(v, l, alpha), d.pdf[k] = ggx_vndf_direction_pdf(v, l, alpha);
  }
  return d;
}

// The LTC half: sample_ltc_lobe at each point, from its clamped-cosine direction.
FL_FLATTEN Directions ltc_half(const brdf::Vec3& view, double alpha, const LtcLobe& ltc,
                               const std::vector<brdf::Vec3>& cosine) {
  Directions d(cosine.size());
  const brdf::Vec3 v = view;
  const LtcLobe lobe = ltc;
#pragma GCC ivdep
  for (size_t k = 0; k < cosine.size(); ++k) {
    const brdf::Vec3 l = ltc_direction(lobe, cosine[k]);
    d.x[k] = l.x, d.y[k] = l.y, d.z[k] = l.z;
    d.target[k] = brdf::ggx_lobe_cos(v, l, alpha), d.pdf[k] = ggx_vndf_direction_pdf(v, l, alpha);
  }
  return d;
}

namespace {

// One half's balance-heuristic terms for a lobe: with the LTC density d_ltc of each direction and
// q = p_vndf + d_ltc, |ρ cos − n_D d_ltc|³ / (n q) of the error and (ρ cos)³ / (n q) of the lobe's
// norm, both 0 where q ≤ 0.
FL_FLATTEN void l3_terms(const LtcLobe& ltc, const Directions& d, double n, double magnitude,
                         double* error, double* norm) {
  const LtcLobe lobe = ltc;
#pragma GCC ivdep
  for (size_t k = 0; k < d.size(); ++k) {
    const double d_ltc = ltc_lobe_density(lobe, {d.x[k], d.y[k], d.z[k]}), b = d.target[k];
    const double q = d.pdf[k] + d_ltc, diff = std::abs(b - magnitude * d_ltc);
    const double error_term = diff * diff * diff / (n * q), lobe_term = b * b * b / (n * q);
    error[k] = q > 0.0 ? error_term : 0.0, norm[k] = q > 0.0 ? lobe_term : 0.0;
  }
}
// Adds the terms to e in the half's order.
void add_l3_terms(const LtcLobe& lobe, const Directions& d, double n, double magnitude,
                  LtcL3Error& e) {
  std::vector<double> error(d.size()), norm(d.size());
  l3_terms(lobe, d, n, magnitude, error.data(), norm.data());
  for (size_t k = 0; k < d.size(); ++k) e.error += error[k], e.lobe += norm[k];
}

}  // namespace

// The balance-heuristic sum over both halves of a direction set for each lobe.
std::vector<LtcL3Error> l3_errors(const brdf::Vec3& v, double alpha, double magnitude,
                                  const Directions& ggx, const LtcPointSet& set,
                                  const std::vector<LtcLobe>& lobes) {
  std::vector<LtcL3Error> out(lobes.size());
  const double n = static_cast<double>(set.cosine.size());
  for (size_t c = 0; c < lobes.size(); ++c) {
    add_l3_terms(lobes[c], ggx, n, magnitude, out[c]);
    add_l3_terms(lobes[c], ltc_half(v, alpha, lobes[c], set.cosine), n, magnitude, out[c]);
  }
  return out;
}

namespace {

// The fitting samples of one half for the proposal, appended to `samples` in the half's order where
// q = p_vndf + p_proposal > 0, with weight 1/√(count q); Σ target³ / (count q) is added to lobe3.
struct SampleTerms {
  std::vector<double> x, y, z, q, weight, lobe3;
  explicit SampleTerms(size_t n) : x(n), y(n), z(n), q(n), weight(n), lobe3(n) {}
};
FL_FLATTEN void sample_terms(const LtcFrame& f, const LtcParams& p, const Directions& d,
                             double count, SampleTerms& out) {
  const LtcFrame frame = f;
  const LtcParams proposal = p;
#pragma GCC ivdep
  for (size_t k = 0; k < d.size(); ++k) {
    const brdf::Vec3 l{d.x[k], d.y[k], d.z[k]};
    const double x = brdf::dot(l, frame.x), y = brdf::dot(l, frame.y), z = brdf::dot(l, frame.z);
    const double q = d.pdf[k] + ltc_density(proposal, x, y, z), t = d.target[k];
    out.x[k] = x, out.y[k] = y, out.z[k] = z, out.q[k] = q;
    out.weight[k] = 1.0 / std::sqrt(count * q), out.lobe3[k] = t * t * t / (count * q);
  }
}
void append_samples(const LtcFrame& frame, const LtcParams& proposal, const Directions& d,
                    double count, std::vector<LtcSample>& samples, double& lobe3) {
  SampleTerms t(d.size());
  sample_terms(frame, proposal, d, count, t);
  for (size_t k = 0; k < d.size(); ++k) {
    if (!(t.q[k] > 0.0)) continue;
    samples.push_back({t.x[k], t.y[k], t.z[k], d.target[k], t.weight[k]});
    lobe3 += t.lobe3[k];
  }
}

}  // namespace

// The fitting directions of a cell: the GGX half (fixed) and the half drawn from the proposal.
LtcProblem assemble_problem(double nov, double alpha, double magnitude, const LtcFrame& frame,
                            const Directions& ggx, const LtcPointSet& set,
                            const LtcParams& proposal) {
  LtcProblem pr{nov, alpha, magnitude, frame, proposal, {}};
  const double count = static_cast<double>(set.cosine.size());
  double lobe3 = 0.0;  // Σ target³ w², the estimate of B₃
  pr.samples.reserve(2 * set.cosine.size());
  append_samples(frame, proposal, ggx, count, pr.samples, lobe3);
  const LtcLobe lobe = ltc_lobe(ltc_matrix(frame, proposal));
  append_samples(frame, proposal, ltc_half(brdf::view_from_nov(nov), alpha, lobe, set.cosine),
                 count, pr.samples, lobe3);
  const double scale = lobe3 > 0.0 ? 1.0 / std::sqrt(lobe3) : 1.0;
  for (auto& smp : pr.samples) smp.weight *= scale;
  return pr;
}

std::vector<LtcL3Error> ltc_l3_errors(double nov, double alpha, double magnitude,
                                      const std::vector<LtcLobe>& lobes, int samples) {
  const brdf::Vec3 v = brdf::view_from_nov(nov);
  const LtcPointSet set = point_set(hammersley_points(std::max(1, samples)));
  return l3_errors(v, alpha, magnitude, ggx_half(v, alpha, set.disk), set, lobes);
}

LtcL3Error ltc_l3_error(double nov, double alpha, double magnitude, const LtcLobe& lobe,
                        int samples) {
  return ltc_l3_errors(nov, alpha, magnitude, {lobe}, samples)[0];
}

LtcProblem make_ltc_problem(double nov, double alpha, double magnitude,
                            const brdf::Vec3& average_dir, const LtcParams& proposal,
                            int sample_sqrt) {
  const LtcPointSet set = point_set(stratified_midpoints(std::max(1, sample_sqrt)));
  return assemble_problem(nov, alpha, magnitude, ltc_frame_from_average_direction(average_dir),
                          ggx_half(brdf::view_from_nov(nov), alpha, set.disk), set, proposal);
}

}  // namespace fl::analysis
