#pragma once
// The data-driven Fresnel basis (docs/basis.md): spectral Fresnel curves R(λ, μ) of the database's
// pages, 1 and (1 − μ)⁵ projected out, the leading left singular vectors of the stacked residuals
// (the SVD construction), then b1..b4 optimized for the pages' ΔE2000 (optimize.h), each written
// as a polynomial in μ. Eigen and Ceres stay inside analysis/basis.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "analysis/pipeline/materials.h"
#include "util/table.h"

namespace fl::analysis {

// Pages whose normal-incidence reflectance (weighted over the construction's wavelengths) is
// below this are left out of the construction, not of the projection tables: the gases
// (|η − 1| ≈ 3e-4, F0 ≈ 1e-8) reflect only within a degree or two of grazing, a spike that
// neither 91 angles nor a polynomial resolves and that no surface a renderer shades has. Every
// condensed phase in the database lies above (F0 = 1e-4 is η ≈ 1.02).
inline constexpr double kBasisMinF0 = 1e-4;

// How each page's curves weigh in the construction (docs/basis.md): all alike; per class, the
// metals' pages sharing `metal_share` of the weight and the others the rest; or by the page's
// perceptual sensitivity, (RMS ΔE2000 / RMS reflectance residual)² of its projection on
// {1, (1 − μ)⁵}, so that reflectance residual energy counts as ΔE2000².
enum class BasisWeighting { Pages, Classes, Perceptual };
const char* basis_weighting_name(BasisWeighting w);                 // pages | classes | perceptual
BasisWeighting basis_weighting_from_name(const std::string& name);  // InputError otherwise

// How b1, b2, ... are chosen (docs/basis.md): b1 = (1 − μ)⁵ and b2.. the leading singular vectors
// of the residuals (Svd), or, from there, b1..b4 by L-BFGS on each page's ΔE2000 (Optimized).
enum class BasisConstruction { Svd, Optimized };
const char* basis_construction_name(BasisConstruction c);                 // svd | optimized
BasisConstruction basis_construction_from_name(const std::string& name);  // InputError otherwise

// The construction's choices (docs/basis.md says why).
struct BasisOptions {
  BasisConstruction construction = BasisConstruction::Optimized;
  int data_terms = 3;          // singular vectors after b1: K = 2..2 + data_terms
  int poly_degree = 10;        // of each data-driven function's polynomial in μ
  int mu_samples = 91;         // μ_j = cos(90°·j/(M − 1)): uniform in θ, as the error metric
  double lambda_step_nm = 10;  // wavelengths 360, 370, ..., 830 nm, weighted by x̄ + ȳ + z̄
  int singular_values = 8;     // listed in the energy table
  BasisWeighting weighting = BasisWeighting::Classes;
  double metal_share = 0.5;  // with BasisWeighting::Classes
  // Also measure every projection as rendered (PageProjection::rendered_de2000).
  bool rendered = false;
};

// μ_j = cos(θ_j), θ_j = 90°·j/(m − 1), j = 0..m − 1 (μ = 1 first, exactly 0 last).
std::vector<double> basis_mu_samples(int m);

// The SVD construction's fixed terms: b0(μ) = 1, b1(μ) = (1 − μ)⁵ (Schlick's).
double basis_fixed_term(int k, double mu);
// Both sampled at `mu`: {b0(μ_j)}, {b1(μ_j)}.
std::vector<std::vector<double>> basis_fixed_span(const std::vector<double>& mu);

// Weighted curves sampled at the same μ values, one row each: r_c(μ_j), weight w_c ≥ 0.
struct CurveRows {
  std::vector<double> values;   // row-major, rows × samples
  std::vector<double> weights;  // per row
  int samples = 0;
  int rows() const { return samples == 0 ? 0 : static_cast<int>(weights.size()); }
};

// The residual subspace of a set of curves (Belcour, Bati & Barla 2020, "Bringing an accurate
// Fresnel to real-time rendering: a pre-integrable decomposition", §4: SVD of Fresnel curves):
// each row minus its least-squares projection on span{1, (1 − μ)⁵} over the samples, scaled by
// √w, stacked; the stack's right singular vectors (functions of μ: the left singular vectors of
// the μ × curves matrix) and singular values. Vectors are unit-norm under Σ_j f(μ_j)g(μ_j), the
// sign making the largest-magnitude sample positive.
struct ResidualSvd {
  std::vector<double> singular_values;         // all `samples` of them, descending
  std::vector<std::vector<double>> functions;  // the first `terms` right singular vectors
  double total_energy = 0;                     // Σ w‖r‖²
  double residual_energy = 0;                  // Σ w‖r − P r‖² = Σ σ²
};

// Folds the rows into the stack's triangular factor in blocks (QR of [R; block]), in row order,
// so the result does not depend on threads.
class ResidualStack {
 public:
  explicit ResidualStack(const std::vector<double>& mu);
  ~ResidualStack();
  ResidualStack(const ResidualStack&) = delete;
  ResidualStack& operator=(const ResidualStack&) = delete;
  void add(const CurveRows& rows);
  // Appends another stack's rows (after this one's): its factor and energies.
  void merge(const ResidualStack& other);
  ResidualSvd solve(int terms) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Least-squares polynomial Σ c_i x^i (degree `degree`, c_0 first) through (x_j, f_j).
std::vector<double> fit_polynomial(const std::vector<double>& x, const std::vector<double>& f,
                                   int degree);
// Horner evaluation of c_0 + c_1 x + ... .
double eval_polynomial(const std::vector<double>& c, double x);
// The same polynomial in μ of one in x = 2μ − 1 (binomial expansion).
std::vector<double> centred_to_mu(const std::vector<double>& c);

// Least-squares coefficients of `f` on the functions `basis` (each sampled at the same points).
class Projector {
 public:
  explicit Projector(const std::vector<std::vector<double>>& basis);
  // The coefficients of f, and f − its projection.
  std::vector<double> coefficients(const std::vector<double>& f) const;
  std::vector<double> residual(const std::vector<double>& f) const;

 private:
  std::vector<std::vector<double>> basis_;
  std::vector<double> pinv_;  // terms × samples
};

// A data-driven term. Its polynomial is fitted in x = 2μ − 1 (on [−1, 1] the monomials are far
// better conditioned than on [0, 1]: coefficients stay small and float evaluation accurate).
struct BasisTerm {
  std::vector<double> sampled;      // the normalized function at the μ samples (max |b| = 1)
  std::vector<double> poly;         // its polynomial in x = 2μ − 1, c_0..c_degree
  std::vector<double> poly_mu;      // the same polynomial in μ
  double fit_max = 0, fit_rms = 0;  // polynomial − sampled at the samples
  double dense_max = 0;             // max |polynomial| on 10001 points of [0, 1]
  // Largest |float Horner − double| on those points, of poly (in x) and of poly_mu (in μ).
  double float_max = 0, float_max_mu = 0;
  double average = 0;  // 2∫₀¹ b(μ) μ dμ, the hemispherical average (exact, from the coefficients)
  double operator()(double mu) const { return eval_polynomial(poly, 2 * mu - 1); }
};

// Per page, per K: RMS reflectance residual and RMS ΔE2000 of the per-channel projection.
struct PageProjection {
  std::string page;
  spectral::MaterialClass material_class;
  double f0 = 0;        // normal-incidence reflectance, weighted over the wavelengths
  bool stacked = true;  // part of the construction (f0 ≥ kBasisMinF0)
  // K = 2..2 + data_terms, the Hoffman span, the peer's K = 3..5 by least squares, the peer's K = 4
  // by its two-point projection.
  std::vector<double> rms_reflectance;
  std::vector<double> rms_de2000;
  // With BasisOptions::rendered, per set (as rms_de2000): RMS ΔE2000 as rendered at lut-accuracy's
  // shading points, the lobe integrals by the truth's quadrature (basis_rendered.h).
  std::vector<double> rendered_de2000;
  Coverage coverage;  // how much of the visible range the page measures (the rest is held)
};

// The peer basis of Belcour, Bati & Barla 2020 (belcour.cpp, docs/basis.md), rebuilt from their
// construction: kBelcourCurves synthetic curves R(μ) sampled at kBelcourSamples values of μ
// uniform on [0, 1]: η = 1.1, kBelcourConductors conductors of edge tint 1 (Gulbrandsen 2014) at
// reflectivity 0.1, 0.2, ..., 1 (the last held at kBelcourMaxReflectivity) and dielectrics with η
// uniform over [1.01, 3]; each normalized to (R − R(1))/(1 − R(1)); b1 the magnitude of the
// leading right singular vector; b2.. the leading right singular vectors of the curves less b1;
// each scaled to max |b| = 1. b0 = 1.
inline constexpr int kBelcourCurves = 1000;
inline constexpr int kBelcourSamples = 1000;
inline constexpr int kBelcourConductors = 10;
inline constexpr double kBelcourMaxReflectivity = 1 - 1e-5;
struct PeerBasis {
  std::vector<double> mu;                      // the samples
  std::vector<std::vector<double>> functions;  // b0 = 1, b1, b2, ... at the samples
  std::array<size_t, 2> two_point{};           // their projection's two samples
  // b_k(μ), linear between the samples.
  double operator()(size_t k, double mu) const;
  // Their projection on {1, b1, b2, b3}: c0 = R(1), c1 = 1 − c0, and c2, c3 interpolating the
  // curve's remainder at the two samples (f_at_a, f_at_b: the curve there).
  std::array<double, 4> two_point_coefficients(double f_at_1, double f_at_a, double f_at_b) const;
};
inline constexpr int kBelcourDataTerms = 3;  // b2, b3 (theirs) and b4 (for K = 5)
// The basis with `data_terms` functions after b1 (K = 2 + data_terms; their K = 4 is 2).
PeerBasis belcour_basis(int data_terms);

struct FresnelBasis {
  BasisOptions options;
  std::vector<double> mu;
  std::vector<double> lambda_nm, lambda_weights;  // the construction's wavelengths
  ResidualSvd svd;
  std::vector<BasisTerm> terms;  // b1, b2, ...: every term after b0 = 1
  PeerBasis peer;                // Belcour et al.'s, K = 2 + kBelcourDataTerms
  std::vector<PageProjection> pages;
  std::vector<SkippedMaterial> skipped;
  int requested = 0;
  double min_coverage = 0;  // the coverage the pages were read under (LoadPolicy::min_coverage)
};

// The provenance of the basis's data, for every output: the pages' --min-coverage, how many
// extrapolate (hold a nearest measured value somewhere in 360–830 nm) and the lowest coverage.
std::string basis_coverage_note(const FresnelBasis& b);

// The basis of the loaded pages (in their order; the skipped ones are listed). `progress` gets
// (done, total): the pages stacked, then the pages projected.
FresnelBasis build_basis(const Context& ctx, const MaterialSet& set, const BasisOptions& options,
                         const std::function<void(int, int)>& progress = {});

// The tables of `basis --out`: the functions sampled, the polynomials, the singular values, the
// projection errors (summary and per page).
Table basis_functions_table(const FresnelBasis& b);
Table basis_polynomials_table(const FresnelBasis& b);
Table basis_energy_table(const FresnelBasis& b);
Table basis_projection_table(const Context& ctx, const FresnelBasis& b);
Table basis_pages_table(const FresnelBasis& b);
// With BasisOptions::rendered: the projections' error as rendered per set and class.
Table basis_rendered_table(const Context& ctx, const FresnelBasis& b);

}  // namespace fl::analysis
