// The tables of `basis --out` (docs/basis.md).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/basis/basis.h"
#include "analysis/study/table_notes.h"
#include "util/quantile.h"

namespace fl::analysis {

namespace {

// Full double precision: 17 significant digits read back to the same double.
constexpr int kFullDigits = 17;

Column full(const std::string& name) {
  return {name, kFullDigits, true, true};
}

// b0 = 1; b1.. the terms.
std::string term_name(size_t k) {
  return fmt::format("b{}", k);
}

// The projection sets' labels, in projection_sets' order.
std::vector<std::string> set_labels(const FresnelBasis& b) {
  std::vector<std::string> labels;
  for (size_t k = 2; k <= 1 + b.terms.size(); ++k) labels.push_back(fmt::format("k{}", k));
  labels.push_back("hoffman3");
  for (size_t k = 3; k <= b.peer.functions.size(); ++k)
    labels.push_back(fmt::format("belcour{}", k));
  if (!b.peer.functions.empty()) labels.push_back("belcour4_two_point");
  return labels;
}

// "page (0.123); ..." of the five largest values, largest first: the tail by name (over a few
// hundred pages p99 is the 4th largest).
std::string worst_pages(const std::vector<double>& values,
                        const std::vector<const PageProjection*>& pages) {
  std::string out;
  for (const size_t i : largest_indices(values, 5))
    out += fmt::format("{}{} ({:.3f})", out.empty() ? "" : "; ", pages[i]->page, values[i]);
  return out;
}

}  // namespace

Table basis_functions_table(const FresnelBasis& b) {
  Table t;
  t.name = "basis_functions";
  t.title = "The basis sampled: b0 = 1, the terms' sampled functions and their polynomials";
  t.columns = {full("theta_deg"), full("mu"), full("b0")};
  for (size_t k = 0; k < b.terms.size(); ++k) t.columns.push_back(full(term_name(k + 1)));
  for (size_t k = 0; k < b.terms.size(); ++k) t.columns.push_back(full(term_name(k + 1) + "_poly"));
  const int m = static_cast<int>(b.mu.size());
  for (int j = 0; j < m; ++j) {
    std::vector<Cell> row = {90.0 * j / (m - 1), b.mu[j], basis_fixed_term(0, b.mu[j])};
    for (const auto& term : b.terms) row.push_back(term.sampled[j]);
    for (const auto& term : b.terms) row.push_back(term(b.mu[j]));
    t.rows.push_back(std::move(row));
  }
  t.reading = fmt::format(
      "{} samples uniform in θ (μ = cos θ). b0 = 1; b1.. are {}, each scaled to max |b| = 1 over "
      "the samples with that sample positive.",
      m,
      b.options.construction == BasisConstruction::Svd
          ? "(1 − μ)⁵ and the leading singular vectors of the residuals, orthogonal to b0, b1 and "
            "to each other under Σ_j f(μ_j)g(μ_j)"
          : "the functions optimized for the pages' ΔE2000, orthogonal to b0 under "
            "Σ_j f(μ_j)g(μ_j) (docs/basis.md)");
  return t;
}

Table basis_polynomials_table(const FresnelBasis& b) {
  Table t;
  t.name = "basis_polynomials";
  t.title = "The data-driven terms as polynomials: b(μ) = Σ c_i x^i";
  t.columns = {{"term"}, {"variable"}, {"degree", 0}};
  const int degree = b.options.poly_degree;
  for (int i = 0; i <= degree; ++i) t.columns.push_back(full(fmt::format("c{}", i)));
  t.columns.insert(t.columns.end(), {{"fit_max_abs", 3, true, true},
                                     {"fit_rms", 3, true, true},
                                     {"float32_horner_max", 2, true, true},
                                     {"max_abs_on_0_1", 6},
                                     full("hemispherical_average"),
                                     {"at_mu_0", 6},
                                     {"at_mu_1", 6}});
  for (size_t k = 0; k < b.terms.size(); ++k) {
    const auto& term = b.terms[k];
    for (const bool centred : {true, false}) {
      std::vector<Cell> row = {term_name(k + 1), std::string(centred ? "2mu-1" : "mu"),
                               static_cast<long long>(degree)};
      for (double c : centred ? term.poly : term.poly_mu) row.push_back(c);
      row.insert(row.end(),
                 {term.fit_max, term.fit_rms, centred ? term.float_max : term.float_max_mu,
                  term.dense_max, term.average, term(0.0), term(1.0)});
      t.rows.push_back(std::move(row));
    }
  }
  t.reading =
      "Least squares in x = 2μ − 1 on the samples of basis_functions; the same polynomial "
      "expanded in x = μ. fit_max_abs and fit_rms are its difference from the sampled function "
      "there (whose max |b| is 1); float32_horner_max the largest difference between "
      "Horner's rule in float and in double over 10001 points of [0, 1]; hemispherical_average "
      "2∫₀¹ b(μ) μ dμ (b0's is 1).";
  return t;
}

Table basis_energy_table(const FresnelBasis& b) {
  Table t;
  t.name = "basis_energy";
  t.title = "Energy per singular vector of the stacked residuals (the SVD construction)";
  t.columns = {{"term"},
               full("singular_value"),
               {"residual_share", 6},
               {"residual_share_cumulative", 6},
               {"residual_left_of_total", 3, true, true}};
  double sum2 = 0;
  for (double s : b.svd.singular_values) sum2 += s * s;
  double cumulative = 0;
  const int n = std::min<int>(b.options.singular_values, b.svd.singular_values.size());
  for (int k = 0; k < n; ++k) {
    const double s = b.svd.singular_values[k];
    cumulative += s * s;
    t.rows.push_back({fmt::format("v{}", k + 1), s, s * s / sum2, cumulative / sum2,
                      (sum2 - cumulative) / b.svd.total_energy});
  }
  t.reading = fmt::format(
      "The curves' energy Σ w‖R‖² is {:.6g}; 1 and (1 − μ)⁵ leave {:.6g} of it ({:.3g}), which "
      "the singular vectors v1, v2, ... take in turn (the SVD construction's b2, b3, ...; they "
      "also start the optimized one): residual_share is σ²/Σσ², residual_left_of_total what "
      "remains after the vector as a share of the curves' energy.",
      b.svd.total_energy, b.svd.residual_energy, b.svd.residual_energy / b.svd.total_energy);
  return t;
}

Table basis_projection_table(const Context& ctx, const FresnelBasis& b) {
  Table t;
  t.name = "basis_projection";
  t.title = "Projection error per K over the pages";
  t.columns = {
      {"basis"},           {"class"},           {"pages", 0},         {"refl_rms_median", 5},
      {"refl_rms_p90", 5}, {"refl_rms_max", 5}, {"de2000_median", 4}, {"de2000_p90", 4},
      {"de2000_p99", 4},   {"de2000_max", 4},   {"de2000_worst"}};
  const auto labels = set_labels(b);
  for (size_t s = 0; s < labels.size(); ++s) {
    const std::string low = fmt::format("f0_below_{:g}", kBasisMinF0);
    for (const std::string cls :
         {std::string("metal"), std::string("dielectric"), low, std::string("all")}) {
      std::vector<double> refl, de;
      std::vector<const PageProjection*> of;
      for (const auto& p : b.pages) {
        const std::string c = p.stacked ? spectral::to_string(p.material_class) : low;
        if (cls != "all" && c != cls) continue;
        refl.push_back(p.rms_reflectance[s]);
        de.push_back(p.rms_de2000[s]);
        of.push_back(&p);
      }
      t.rows.push_back({labels[s], std::string(cls), static_cast<long long>(refl.size()),
                        median(refl), quantile(refl, 0.9), quantile(refl, 1.0), median(de),
                        quantile(de, 0.9), quantile(de, 0.99), quantile(de, 1.0),
                        worst_pages(de, of)});
    }
  }
  t.reading =
      "kK: the first K terms (b0 = 1, b1, ...); hoffman3: 1, (1 − μ)⁵, "
      "μ(1 − μ)⁶; belcourK: the first K functions of Belcour, Bati & Barla 2020's basis "
      "(rebuilt from their construction; K = 5 adds the next singular vector), least squares; "
      "belcour4_two_point: their K = 4 with their projection (R(0°), 1 − R(0°), two angles). "
      "refl_rms: RMS over the samples of the spectral curve's least-squares residual, "
      "weighted over the wavelengths; de2000: RMS ΔE2000 over the angles of the RGB truth curve "
      "projected per channel (least squares over the angles). f0_below_...: the pages left out "
      "of the construction (gases, whose curve is a spike at grazing that no basis follows); "
      "metal and dielectric exclude them, all includes them. de2000_worst: the five worst pages.";
  t.notes = {setting_note(ctx), basis_coverage_note(b),
             "Median, p90 and p99 by nearest rank: the value of rank ⌈q·n⌉ in ascending order."};
  return t;
}

Table basis_rendered_table(const Context& ctx, const FresnelBasis& b) {
  Table t;
  t.name = "basis_rendered";
  t.title = "Projection error per K as rendered, over the pages";
  t.columns = {{"basis"},  {"class"},  {"pages", 0}, {"median", 4},
               {"p90", 4}, {"p99", 4}, {"max", 4},   {"worst"}};
  const auto labels = set_labels(b);
  const std::string low = fmt::format("f0_below_{:g}", kBasisMinF0);
  for (size_t s = 0; s < labels.size(); ++s)
    for (const std::string cls : {std::string("metal"), std::string("dielectric"), low}) {
      std::vector<double> de;
      std::vector<const PageProjection*> of;
      for (const auto& p : b.pages) {
        const std::string c = p.stacked ? spectral::to_string(p.material_class) : low;
        if (c != cls || p.rendered_de2000.size() <= s) continue;
        de.push_back(p.rendered_de2000[s]);
        of.push_back(&p);
      }
      if (de.empty()) continue;
      t.rows.push_back({labels[s], cls, static_cast<long long>(de.size()), median(de),
                        quantile(de, 0.9), quantile(de, 0.99), quantile(de, 1.0),
                        worst_pages(de, of)});
    }
  t.reading =
      "Per page, the RMS ΔE2000 over lut-accuracy's shading points (perceptual roughness 0.2..1 × "
      "view 0°..85°) between the GGX lobe integrated with the spectral ground truth and the "
      "engine's Σ_t c_t·∫b_t ρ cos per channel, with c the least-squares projection of the RGB "
      "curve over the 91 angles (belcour4_two_point: their own projection); the lobe integrals by "
      "the truth's own quadrature, as tables of infinite resolution would hold them. worst: the "
      "five worst pages of the class.";
  t.notes = {setting_note(ctx), basis_coverage_note(b),
             "Median, p90 and p99 by nearest rank: the value of rank ⌈q·n⌉ in ascending order."};
  return t;
}

Table basis_pages_table(const FresnelBasis& b) {
  Table t;
  t.name = "basis_pages";
  t.title = "Projection error per page";
  t.columns = {{"page"}, {"class"}, {"f0", 6, true, true}, {"in_basis"}};
  const auto labels = set_labels(b);
  for (const auto& l : labels) t.columns.push_back({"refl_rms_" + l, 5});
  for (const auto& l : labels) t.columns.push_back({"de2000_" + l, 4});
  for (const char* c : {"coverage", "coverage_n", "coverage_k"}) t.columns.push_back({c, 4});
  t.columns.push_back({"extrapolated"});
  for (const auto& p : b.pages) {
    std::vector<Cell> row = {p.page, std::string(spectral::to_string(p.material_class)), p.f0,
                             std::string(p.stacked ? "yes" : "no")};
    for (double v : p.rms_reflectance) row.push_back(v);
    for (double v : p.rms_de2000) row.push_back(v);
    const auto& c = p.coverage;
    row.insert(row.end(), {c.both, c.n, c.k, std::string(c.extrapolated ? "yes" : "no")});
    t.rows.push_back(std::move(row));
  }
  t.notes = {basis_coverage_note(b)};
  return t;
}

std::string basis_coverage_note(const FresnelBasis& b) {
  int held = 0;
  const PageProjection* lowest = nullptr;
  for (const auto& p : b.pages) {
    held += p.coverage.extrapolated;
    if (!lowest || p.coverage.both < lowest->coverage.both) lowest = &p;
  }
  return fmt::format(
      "Pages read with --min-coverage {:g}: {} of {} extrapolate (hold the nearest measured value "
      "somewhere in 360-830 nm; coverage: the share measured, weighted by the illuminant x "
      "ybar){}.",
      b.min_coverage, held, b.pages.size(),
      lowest ? fmt::format("; lowest coverage {:.4f} ({})", lowest->coverage.both, lowest->page)
             : "");
}

}  // namespace fl::analysis
