// The basis of the database's pages: the curves, their stacked residuals, the terms, each page's
// projection.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "analysis/basis/basis.h"
#include "analysis/basis/basis_rendered.h"
#include "analysis/basis/optimize.h"
#include "analysis/lut/lut_accuracy.h"
#include "fresnel/exact.h"
#include "spectral/cie.h"
#include "util/errors.h"
#include "util/parallel.h"

namespace fl::analysis {

namespace {

// Pages per block of the stack: each block's QR runs on its own thread, the blocks fold in order.
constexpr size_t kBlockPages = 32;
// Points of [0, 1] on which a polynomial's largest magnitude is taken.
constexpr int kDensePoints = 10001;

struct Wavelengths {
  std::vector<int> index;  // into the context's grid
  std::vector<double> lambda_nm, weights;
};

// Every `step_nm` from 360 nm, weighted by x̄ + ȳ + z̄ (CIE 1931 2°), normalized to sum 1.
Wavelengths construction_wavelengths(const Context& ctx, double step_nm) {
  const auto observer = spectral::cie1931_2deg(ctx.grid());
  Wavelengths w;
  double sum = 0;
  for (int i = 0; i < ctx.grid().count; ++i) {
    const double lambda = ctx.grid().lambda_nm(i);
    if (std::abs(std::remainder(lambda - ctx.grid().start_nm, step_nm)) > 1e-9) continue;
    const double cmf =
        observer.x_bar.values[i] + observer.y_bar.values[i] + observer.z_bar.values[i];
    w.index.push_back(i);
    w.lambda_nm.push_back(lambda);
    w.weights.push_back(cmf);
    sum += cmf;
  }
  for (auto& v : w.weights) v /= sum;
  return w;
}

// R(λ, μ_j) for each construction wavelength (exact unpolarized Fresnel, index relative to the
// outside medium), weighted by the wavelength's weight.
void add_page_rows(const spectral::ComplexIorSpectrum& ior, const Wavelengths& w,
                   const std::vector<double>& mu, double eta_outside, CurveRows& rows,
                   double page_weight = 1.0) {
  for (size_t l = 0; l < w.index.size(); ++l) {
    const std::complex<double> eta = ior.ior[w.index[l]] / eta_outside;
    for (double m : mu) rows.values.push_back(fresnel::fresnel_conductor(m, eta));
    rows.weights.push_back(page_weight * w.weights[l]);
  }
}

// The function sets projected on: K = 2..1 + terms (b0 = 1, then the terms' polynomials), then
// Hoffman's span {1, (1 − μ)⁵, μ(1 − μ)⁶}, then the peer's first 3, 4, 5 functions (as many
// as it has), each sampled at `points`.
std::vector<std::vector<std::vector<double>>> projection_sets(const std::vector<BasisTerm>& terms,
                                                              const PeerBasis* peer,
                                                              const std::vector<double>& points) {
  auto sample = [&](auto&& f) {
    std::vector<double> v;
    for (double m : points) v.push_back(f(m));
    return v;
  };
  std::vector<std::vector<double>> functions = {
      sample([](double m) { return basis_fixed_term(0, m); })};
  std::vector<std::vector<std::vector<double>>> sets;
  for (const auto& t : terms) {
    functions.push_back(sample([&](double m) { return t(m); }));
    if (functions.size() >= 2) sets.push_back(functions);
  }
  sets.push_back({functions[0], sample([](double m) { return basis_fixed_term(1, m); }),
                  sample([](double m) { return m * std::pow(1.0 - m, 6); })});
  if (!peer) return sets;
  std::vector<std::vector<double>> theirs;
  for (size_t k = 0; k < peer->functions.size(); ++k) {
    theirs.push_back(sample([&](double m) { return (*peer)(k, m); }));
    if (theirs.size() >= 3) sets.push_back(theirs);
  }
  return sets;
}

// The peer's own projection of one curve f(μ) sampled at `points` (f_at(μ) gives the curve at
// any μ): f − Σ c_k b_k at the points.
template <class F>
std::vector<double> two_point_residual(const PeerBasis& peer, const std::vector<double>& points,
                                       const std::vector<double>& f, F&& f_at,
                                       std::vector<double>* coefficients = nullptr) {
  const auto c = peer.two_point_coefficients(f_at(1.0), f_at(peer.mu[peer.two_point[0]]),
                                             f_at(peer.mu[peer.two_point[1]]));
  if (coefficients) coefficients->assign(c.begin(), c.end());
  std::vector<double> r = f;
  for (size_t j = 0; j < points.size(); ++j)
    for (size_t k = 0; k < c.size(); ++k) r[j] -= c[k] * peer(k, points[j]);
  return r;
}

// Normal-incidence reflectance weighted over the construction's wavelengths.
double weighted_f0(const spectral::ComplexIorSpectrum& ior, const Wavelengths& w,
                   double eta_outside) {
  double f0 = 0;
  for (size_t l = 0; l < w.index.size(); ++l)
    f0 += w.weights[l] * fresnel::fresnel_conductor(1.0, ior.ior[w.index[l]] / eta_outside);
  return f0;
}

ResidualSvd stack_residuals(const std::vector<const LoadedMaterial*>& pages,
                            const std::vector<double>& weights, const Wavelengths& w,
                            const std::vector<double>& mu, double eta_outside, int terms,
                            const std::function<void(int, int)>& progress) {
  const size_t blocks = (pages.size() + kBlockPages - 1) / kBlockPages;
  std::vector<std::unique_ptr<ResidualStack>> stacks(blocks);
  ProgressCounter counter(progress, static_cast<int>(pages.size()));
  parallel_for(blocks, [&](size_t b) {
    CurveRows rows;
    rows.samples = static_cast<int>(mu.size());
    const size_t end = std::min(pages.size(), (b + 1) * kBlockPages);
    for (size_t p = b * kBlockPages; p < end; ++p)
      add_page_rows(pages[p]->ior, w, mu, eta_outside, rows, weights[p]);
    stacks[b] = std::make_unique<ResidualStack>(mu);
    stacks[b]->add(rows);
    counter.add(static_cast<int>(end - b * kBlockPages));
  });
  ResidualStack all(mu);
  for (const auto& s : stacks) all.merge(*s);
  return all.solve(terms);
}

// Largest |float Horner − double| of a polynomial in x = scale·μ + shift on the dense points.
double float_error(const std::vector<double>& c, double scale, double shift) {
  double worst = 0;
  for (int i = 0; i < kDensePoints; ++i) {
    const double x = scale * (double(i) / (kDensePoints - 1)) + shift;
    float p = 0.0f;
    for (size_t k = c.size(); k-- > 0;) p = p * static_cast<float>(x) + static_cast<float>(c[k]);
    worst = std::max(worst, std::abs(double(p) - eval_polynomial(c, x)));
  }
  return worst;
}

// A function scaled to max |b| = 1 over the samples with that sample positive, and its
// polynomial.
BasisTerm make_term(const std::vector<double>& mu, const std::vector<double>& vector, int degree) {
  BasisTerm t;
  double peak = 0;
  for (double v : vector)
    if (std::abs(v) > std::abs(peak)) peak = v;
  for (double v : vector) t.sampled.push_back(v / peak);
  std::vector<double> x;
  for (double m : mu) x.push_back(2 * m - 1);
  t.poly = fit_polynomial(x, t.sampled, degree);
  t.poly_mu = centred_to_mu(t.poly);
  double sum2 = 0;
  for (size_t j = 0; j < mu.size(); ++j) {
    const double e = std::abs(t(mu[j]) - t.sampled[j]);
    t.fit_max = std::max(t.fit_max, e);
    sum2 += e * e;
  }
  t.fit_rms = std::sqrt(sum2 / mu.size());
  for (int i = 0; i < kDensePoints; ++i)
    t.dense_max = std::max(t.dense_max, std::abs(t(double(i) / (kDensePoints - 1))));
  // Kulla & Conty 2017, F_avg = 2∫₀¹ F(μ) μ dμ; with μ = (x + 1)/2 each x^i contributes
  // ∫₋₁¹ x^i (x + 1) dx / 2: 1/(i + 2) for odd i, 1/(i + 1) for even i.
  for (size_t i = 0; i < t.poly.size(); ++i) t.average += t.poly[i] / double(i % 2 ? i + 2 : i + 1);
  t.float_max = float_error(t.poly, 2.0, -1.0);
  t.float_max_mu = float_error(t.poly_mu, 1.0, 0.0);
  return t;
}

// The peer's two-point projection's errors, appended to the page's.
std::array<std::vector<double>, 3> add_two_point(const Context& ctx, const LoadedMaterial& page,
                                                 const Wavelengths& w,
                                                 const std::vector<double>& mu,
                                                 const PeerBasis& peer,
                                                 const std::vector<color::Rgb>& truth,
                                                 PageProjection& out) {
  const double eta_outside = ctx.settings().eta_outside;
  double sum = 0;
  for (size_t l = 0; l < w.index.size(); ++l) {
    const std::complex<double> eta = page.ior.ior[w.index[l]] / eta_outside;
    const auto at = [&](double m) { return fresnel::fresnel_conductor(m, eta); };
    std::vector<double> f;
    for (double m : mu) f.push_back(at(m));
    double e2 = 0;
    for (double r : two_point_residual(peer, mu, f, at)) e2 += r * r;
    sum += w.weights[l] * e2 / mu.size();
  }
  out.rms_reflectance.push_back(std::sqrt(sum));
  std::vector<color::Rgb> approx = truth;
  std::array<std::vector<double>, 3> coefficients;
  std::vector<color::Rgb> at_mu;
  for (double m : {1.0, peer.mu[peer.two_point[0]], peer.mu[peer.two_point[1]]})
    at_mu.push_back(ground_truth_rgb(ctx, page.ior, m, eta_outside));
  for (int c = 0; c < 3; ++c) {
    std::vector<double> channel;
    for (const auto& rgb : truth) channel.push_back(rgb[c]);
    const auto at = [&](double m) {
      return m == 1.0 ? at_mu[0][c] : m == peer.mu[peer.two_point[0]] ? at_mu[1][c] : at_mu[2][c];
    };
    const auto r = two_point_residual(peer, ctx.cos_thetas(), channel, at, &coefficients[c]);
    for (size_t j = 0; j < r.size(); ++j) approx[j][c] -= r[j];
  }
  out.rms_de2000.push_back(curve_error(ctx, truth, approx).rms);
  return coefficients;
}

PageProjection project_page(const Context& ctx, const LoadedMaterial& page, const Wavelengths& w,
                            const std::vector<double>& mu,
                            const std::vector<Projector>& spectral_projectors,
                            const std::vector<Projector>& rgb_projectors,
                            const PeerBasis* peer = nullptr,
                            const RenderedSets* rendered = nullptr) {
  const double eta_outside = ctx.settings().eta_outside;
  PageProjection out{page.material.source, page.material.material_class,
                     weighted_f0(page.ior, w, eta_outside)};
  out.stacked = out.f0 >= kBasisMinF0;
  out.coverage = page.coverage;
  CurveRows rows;
  rows.samples = static_cast<int>(mu.size());
  add_page_rows(page.ior, w, mu, eta_outside, rows);
  for (const auto& proj : spectral_projectors) {
    double sum = 0;
    for (int l = 0; l < rows.rows(); ++l) {
      const std::vector<double> f(rows.values.begin() + size_t(l) * mu.size(),
                                  rows.values.begin() + size_t(l + 1) * mu.size());
      double e2 = 0;
      for (double r : proj.residual(f)) e2 += r * r;
      sum += rows.weights[l] * e2 / mu.size();
    }
    out.rms_reflectance.push_back(std::sqrt(sum));
  }
  const auto truth = ground_truth_curve(ctx, page.ior, eta_outside);
  std::vector<std::array<std::vector<double>, 3>> coefficients;
  for (const auto& proj : rgb_projectors) {
    std::vector<color::Rgb> approx = truth;
    coefficients.emplace_back();
    for (int c = 0; c < 3; ++c) {
      std::vector<double> channel;
      for (const auto& rgb : truth) channel.push_back(rgb[c]);
      coefficients.back()[c] = proj.coefficients(channel);
      const auto r = proj.residual(channel);
      for (size_t j = 0; j < r.size(); ++j) approx[j][c] -= r[j];
    }
    out.rms_de2000.push_back(curve_error(ctx, truth, approx).rms);
  }
  if (peer) coefficients.push_back(add_two_point(ctx, page, w, mu, *peer, truth, out));
  if (rendered) {
    const auto lobe = lobe_truth(ctx, page, rendered->points);
    for (size_t s = 0; s < coefficients.size(); ++s)
      out.rendered_de2000.push_back(
          rendered_rms(ctx, lobe, rendered->integrals[s], coefficients[s]));
  }
  return out;
}

// Each stacked page's weight (BasisWeighting): 1; per class, the metals' weights summing to
// metal_share·n and the others' to (1 − metal_share)·n (n pages, so that they average 1); or the
// page's sensitivity (RMS ΔE2000 / RMS reflectance residual)² on {1, (1 − μ)⁵}.
std::vector<double> page_weights(const Context& ctx,
                                 const std::vector<const LoadedMaterial*>& pages,
                                 const Wavelengths& w, const std::vector<double>& mu,
                                 const BasisOptions& options) {
  std::vector<double> weight(pages.size(), 1.0);
  if (options.weighting == BasisWeighting::Perceptual) {
    const std::vector<Projector> spectral = {Projector(basis_fixed_span(mu))};
    const std::vector<Projector> rgb = {Projector(basis_fixed_span(ctx.cos_thetas()))};
    parallel_for(pages.size(), [&](size_t i) {
      const auto p = project_page(ctx, *pages[i], w, mu, spectral, rgb);
      weight[i] = std::pow(p.rms_de2000[0] / p.rms_reflectance[0], 2);
    });
  }
  if (options.weighting != BasisWeighting::Classes) return weight;
  auto metal = [&](size_t i) {
    return pages[i]->material.material_class == spectral::MaterialClass::Metal ? 1 : 0;
  };
  size_t count[2] = {0, 0};
  for (size_t i = 0; i < pages.size(); ++i) ++count[metal(i)];
  const double n = static_cast<double>(pages.size());
  for (size_t i = 0; i < pages.size(); ++i)
    weight[i] = n * (metal(i) ? options.metal_share : 1.0 - options.metal_share) /
                static_cast<double>(count[metal(i)]);
  return weight;
}

// b1, b2, ...: (1 − μ)⁵ and the SVD's functions, or those optimized from them.
std::vector<BasisTerm> basis_terms(const Context& ctx,
                                   const std::vector<const LoadedMaterial*>& pages,
                                   const FresnelBasis& b, ProgressCounter& counter) {
  const int degree = b.options.poly_degree;
  std::vector<BasisTerm> terms;
  if (b.options.construction == BasisConstruction::Svd) {
    terms.push_back(make_term(b.mu, basis_fixed_span(b.mu)[1], degree));
    for (const auto& v : b.svd.functions) terms.push_back(make_term(b.mu, v, degree));
    return terms;
  }
  if (b.svd.functions.size() != 3)
    throw InputError("basis: --construction optimized starts from 3 singular vectors (--terms 3)");
  // The optimization samples the context's angles; the construction's samples must be the same.
  const auto& angles = ctx.cos_thetas();
  bool same = angles.size() == b.mu.size();
  for (size_t j = 0; same && j < angles.size(); ++j) same = std::abs(angles[j] - b.mu[j]) < 1e-12;
  if (!same)
    throw InputError(
        "basis: --construction optimized samples 91 angles uniform in θ; drop --angles or use "
        "--construction svd");
  std::vector<std::vector<double>> initial;
  for (const auto& v : b.svd.functions) {
    const auto t = make_term(b.mu, v, degree);
    initial.emplace_back();
    for (double m : ctx.cos_thetas()) initial.back().push_back(t(m));
  }
  for (const auto& c : optimize_terms(ctx, pages, initial, degree, [&] { counter.add(1); })) {
    std::vector<double> v;
    for (double m : b.mu) v.push_back(eval_polynomial(c, 2 * m - 1));
    terms.push_back(make_term(b.mu, v, degree));
  }
  return terms;
}

}  // namespace

// Every page's projection errors on every set (and as rendered, with BasisOptions::rendered).
void project_pages(const Context& ctx, const std::vector<LoadedMaterial>& pages,
                   const Wavelengths& w, FresnelBasis& b, ProgressCounter& counter) {
  std::vector<Projector> spectral_projectors, rgb_projectors;
  for (const auto& set : projection_sets(b.terms, &b.peer, b.mu))
    spectral_projectors.emplace_back(set);
  for (const auto& set : projection_sets(b.terms, &b.peer, ctx.cos_thetas()))
    rgb_projectors.emplace_back(set);
  std::optional<RenderedSets> rendered;
  if (b.options.rendered) {
    const auto& nodes = truth_nodes();
    auto sets = projection_sets(b.terms, &b.peer, std::vector<double>(nodes.begin(), nodes.end()));
    sets.push_back(sets.back());  // the peer's two-point projection: its K = 4 functions
    sets.back().resize(4);
    rendered = rendered_sets(sets, lut_accuracy_points());
  }
  b.pages.resize(pages.size());
  parallel_for(pages.size(), [&](size_t i) {
    b.pages[i] = project_page(ctx, pages[i], w, b.mu, spectral_projectors, rgb_projectors, &b.peer,
                              rendered ? &*rendered : nullptr);
    counter.add(1);
  });
}

FresnelBasis build_basis(const Context& ctx, const MaterialSet& set, const BasisOptions& options,
                         const std::function<void(int, int)>& progress) {
  const auto& pages = set.materials;
  FresnelBasis b;
  b.skipped = set.skipped;
  b.requested = set.requested;
  b.options = options;
  b.mu = basis_mu_samples(options.mu_samples);
  const Wavelengths w = construction_wavelengths(ctx, options.lambda_step_nm);
  b.lambda_nm = w.lambda_nm;
  b.lambda_weights = w.weights;
  std::vector<const LoadedMaterial*> stacked;
  for (const auto& p : pages)
    if (weighted_f0(p.ior, w, ctx.settings().eta_outside) >= kBasisMinF0) stacked.push_back(&p);
  // Progress units: the pages stacked, the L-BFGS runs, the pages projected.
  const int rounds =
      options.construction == BasisConstruction::Optimized ? kOptimizeRoundsTotal : 0;
  const int total = static_cast<int>(stacked.size() + pages.size()) + rounds;
  b.svd = stack_residuals(stacked, page_weights(ctx, stacked, w, b.mu, options), w, b.mu,
                          ctx.settings().eta_outside, options.data_terms, [&](int done, int) {
                            if (progress) progress(done, total);
                          });
  ProgressCounter counter(progress, total, static_cast<int>(stacked.size()));
  b.terms = basis_terms(ctx, stacked, b, counter);
  b.peer = belcour_basis(kBelcourDataTerms);
  project_pages(ctx, pages, w, b, counter);
  return b;
}

}  // namespace fl::analysis
