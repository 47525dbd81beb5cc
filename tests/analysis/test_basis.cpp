// The data-driven Fresnel basis (analysis/basis/basis.h) against independent computations: curves
// built from known functions, whose residual span, singular values and energies follow from
// their coefficients in closed form; polynomial fits against the normal equations.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/basis/basis.h"
#include "csv_reader.h"
#include "fresnel/basis.h"
#include "fresnel/exact.h"

namespace fl::analysis {
namespace {

// Sums over 91 samples of values of order 1: a few hundred roundings of 1e-16.
constexpr double kRoundoff = 1e-12;
// A rank-2 stack's third singular value relative to its first: zero up to QR/SVD roundoff.
constexpr double kRankTolerance = 1e-12;

using Vec = std::vector<double>;

double dot(const Vec& a, const Vec& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// a − its projection on span{1, (1 − μ)⁵} by Gram–Schmidt (independent of the QR in basis.cpp).
Vec minus_fixed_span(const Vec& mu, Vec a) {
  Vec e0(mu.size(), 1.0 / std::sqrt(double(mu.size()))), e1;
  for (double m : mu) e1.push_back(std::pow(1.0 - m, 5));
  const double c = dot(e1, e0);
  for (size_t j = 0; j < mu.size(); ++j) e1[j] -= c * e0[j];
  const double n1 = std::sqrt(dot(e1, e1));
  for (auto& v : e1) v /= n1;
  const double a0 = dot(a, e0), a1 = dot(a, e1);
  for (size_t j = 0; j < mu.size(); ++j) a[j] -= a0 * e0[j] + a1 * e1[j];
  return a;
}

// A deterministic spread of coefficients in [−1, 1].
double coefficient(int i, int k) {
  return std::sin(1.7 * i + 2.3 * k + 0.4 * i * k);
}

struct Synthetic {
  Vec mu;
  std::vector<Vec> shapes;  // the data-driven shapes the curves hold
  CurveRows rows;
};

// Curves a + b(1 − μ)⁵ + Σ c_k shape_k with weights 0.5..1.5.
Synthetic synthetic_curves(int curves) {
  Synthetic s;
  s.mu = basis_mu_samples(91);
  s.shapes.resize(2);
  for (double m : s.mu) {
    s.shapes[0].push_back(m * std::pow(1.0 - m, 6));
    s.shapes[1].push_back(m * m * (1.0 - m) * std::cos(3 * m));
  }
  s.rows.samples = 91;
  for (int i = 0; i < curves; ++i) {
    for (size_t j = 0; j < s.mu.size(); ++j) {
      double v = 0.3 + coefficient(i, 0) * 0.2 + coefficient(i, 1) * std::pow(1 - s.mu[j], 5);
      for (size_t k = 0; k < s.shapes.size(); ++k) v += coefficient(i, 2 + k) * s.shapes[k][j];
      s.rows.values.push_back(v);
    }
    s.rows.weights.push_back(1.0 + 0.5 * coefficient(i, 7));
  }
  return s;
}

TEST(Basis, FixedTermsAreOneAndSchlicksPower) {
  for (double mu : basis_mu_samples(91)) {
    EXPECT_EQ(basis_fixed_term(0, mu), 1.0);
    EXPECT_NEAR(basis_fixed_term(1, mu), std::pow(1.0 - mu, 5), 4e-16);
  }
}

TEST(Basis, SamplesAreUniformInTheta) {
  const Vec mu = basis_mu_samples(91);
  ASSERT_EQ(mu.size(), 91u);
  EXPECT_EQ(mu.front(), 1.0);
  EXPECT_EQ(mu.back(), 0.0);
  for (int j = 0; j < 91; ++j) EXPECT_NEAR(mu[j], std::cos(j * std::numbers::pi / 180), 1e-15);
}

TEST(Basis, SvdRecoversTheSpanOfKnownShapes) {
  const Synthetic s = synthetic_curves(300);
  ResidualStack stack(s.mu);
  stack.add(s.rows);
  const ResidualSvd svd = stack.solve(3);
  ASSERT_EQ(svd.singular_values.size(), 91u);
  EXPECT_LT(svd.singular_values[2], kRankTolerance * svd.singular_values[0]);
  // Each shape, off the fixed span, lies in span{u1, u2}.
  for (const auto& shape : s.shapes) {
    Vec r = minus_fixed_span(s.mu, shape);
    const double norm = std::sqrt(dot(r, r));
    for (int k = 0; k < 2; ++k) {
      const double c = dot(r, svd.functions[k]);
      for (size_t j = 0; j < r.size(); ++j) r[j] -= c * svd.functions[k][j];
    }
    EXPECT_LT(std::sqrt(dot(r, r)), 1e-10 * norm);
  }
}

// σ² are the eigenvalues of H·C: C = Σ w c cᵀ over the shapes' coefficients, H the Gram matrix of
// the shapes off the fixed span (a 2 × 2 eigenproblem solved in closed form here).
TEST(Basis, SingularValuesAndEnergiesMatchClosedForms) {
  const Synthetic s = synthetic_curves(300);
  ResidualStack stack(s.mu);
  stack.add(s.rows);
  const ResidualSvd svd = stack.solve(2);
  const Vec g0 = minus_fixed_span(s.mu, s.shapes[0]), g1 = minus_fixed_span(s.mu, s.shapes[1]);
  const double h[2][2] = {{dot(g0, g0), dot(g0, g1)}, {dot(g1, g0), dot(g1, g1)}};
  double c[2][2] = {{0, 0}, {0, 0}}, total = 0;
  for (int i = 0; i < s.rows.rows(); ++i) {
    const double w = s.rows.weights[i], a = coefficient(i, 2), b = coefficient(i, 3);
    c[0][0] += w * a * a, c[0][1] += w * a * b, c[1][0] += w * a * b, c[1][1] += w * b * b;
    const Vec f(s.rows.values.begin() + i * 91, s.rows.values.begin() + (i + 1) * 91);
    total += w * dot(f, f);
  }
  const double m00 = h[0][0] * c[0][0] + h[0][1] * c[1][0],
               m01 = h[0][0] * c[0][1] + h[0][1] * c[1][1],
               m10 = h[1][0] * c[0][0] + h[1][1] * c[1][0],
               m11 = h[1][0] * c[0][1] + h[1][1] * c[1][1];
  const double tr = m00 + m11, det = m00 * m11 - m01 * m10;
  const double disc = std::sqrt(tr * tr / 4 - det);
  EXPECT_NEAR(svd.singular_values[0] * svd.singular_values[0], tr / 2 + disc,
              kRoundoff * (tr / 2 + disc));
  EXPECT_NEAR(svd.singular_values[1] * svd.singular_values[1], tr / 2 - disc,
              1e-9 * (tr / 2 + disc));
  EXPECT_NEAR(svd.total_energy, total, kRoundoff * total);
  double sum2 = 0;
  for (double v : svd.singular_values) sum2 += v * v;
  EXPECT_NEAR(svd.residual_energy, sum2, kRoundoff * total);
  EXPECT_NEAR(svd.residual_energy, tr, 1e-9 * tr);
}

TEST(Basis, FunctionsAreOrthogonalToEachOtherAndTheFixedTerms) {
  Synthetic s = synthetic_curves(400);
  // A third shape so that three terms carry energy.
  for (int i = 0; i < s.rows.rows(); ++i)
    for (int j = 0; j < 91; ++j)
      s.rows.values[i * 91 + j] += 0.1 * coefficient(i, 9) * std::pow(s.mu[j], 3);
  ResidualStack stack(s.mu);
  stack.add(s.rows);
  const ResidualSvd svd = stack.solve(3);
  Vec ones(91, 1.0), schlick;
  for (double m : s.mu) schlick.push_back(std::pow(1 - m, 5));
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(dot(svd.functions[a], svd.functions[a]), 1.0, kRoundoff);
    EXPECT_NEAR(dot(svd.functions[a], ones), 0.0, kRoundoff);
    EXPECT_NEAR(dot(svd.functions[a], schlick), 0.0, kRoundoff);
    for (int b = a + 1; b < 3; ++b)
      EXPECT_NEAR(dot(svd.functions[a], svd.functions[b]), 0.0, kRoundoff);
    // Sign convention: the largest-magnitude sample is positive.
    double peak = 0;
    for (double v : svd.functions[a])
      if (std::abs(v) > std::abs(peak)) peak = v;
    EXPECT_GT(peak, 0.0);
  }
}

TEST(Basis, BlocksMergedInOrderGiveTheWholeStack) {
  const Synthetic s = synthetic_curves(300);
  ResidualStack whole(s.mu), merged(s.mu);
  whole.add(s.rows);
  for (int start = 0; start < 300; start += 70) {
    CurveRows part;
    part.samples = 91;
    const int end = std::min(300, start + 70);
    part.values.assign(s.rows.values.begin() + start * 91, s.rows.values.begin() + end * 91);
    part.weights.assign(s.rows.weights.begin() + start, s.rows.weights.begin() + end);
    ResidualStack block(s.mu);
    block.add(part);
    merged.merge(block);
  }
  const auto a = whole.solve(2), b = merged.solve(2);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(a.singular_values[k], b.singular_values[k], kRoundoff * a.singular_values[0]);
    for (int j = 0; j < 91; ++j) EXPECT_NEAR(a.functions[k][j], b.functions[k][j], 1e-10);
  }
}

TEST(Basis, PolynomialFitSatisfiesTheNormalEquations) {
  const Vec mu = basis_mu_samples(91);
  Vec f;
  for (double m : mu) f.push_back(std::exp(-4 * m) * std::sin(5 * m));
  const Vec c = fit_polynomial(mu, f, 8);
  ASSERT_EQ(c.size(), 9u);
  // The residual is orthogonal to every monomial up to the degree.
  for (int i = 0; i <= 8; ++i) {
    double s = 0;
    for (size_t j = 0; j < mu.size(); ++j)
      s += (eval_polynomial(c, mu[j]) - f[j]) * std::pow(mu[j], i);
    EXPECT_NEAR(s, 0.0, 1e-10) << "monomial " << i;
  }
  // A polynomial of the degree is reproduced.
  Vec p;
  for (double m : mu) p.push_back(0.5 - 2 * m + 3 * m * m * m - m * m * m * m * m * m * m * m);
  const Vec cp = fit_polynomial(mu, p, 8);
  const double expected[9] = {0.5, -2, 0, 3, 0, 0, 0, 0, -1};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(cp[i], expected[i], 1e-8) << "c" << i;
}

TEST(Basis, ProjectorLeavesTheOrthogonalResidual) {
  const Vec mu = basis_mu_samples(91);
  Vec ones(91, 1.0), schlick, hoffman, f;
  for (double m : mu) {
    schlick.push_back(std::pow(1 - m, 5));
    hoffman.push_back(m * std::pow(1 - m, 6));
    f.push_back(0.2 + 0.7 * std::pow(1 - m, 5) - 1.5 * m * std::pow(1 - m, 6) + 0.01 * m * m);
  }
  const Projector p({ones, schlick, hoffman});
  const Vec r = p.residual(f);
  EXPECT_NEAR(dot(r, ones), 0.0, kRoundoff);
  EXPECT_NEAR(dot(r, schlick), 0.0, kRoundoff);
  EXPECT_NEAR(dot(r, hoffman), 0.0, kRoundoff);
  Vec in_span;
  for (size_t j = 0; j < mu.size(); ++j) in_span.push_back(f[j] - 0.01 * mu[j] * mu[j]);
  const Vec c = p.coefficients(in_span);
  EXPECT_NEAR(c[0], 0.2, 1e-12);
  EXPECT_NEAR(c[1], 0.7, 1e-12);
  EXPECT_NEAR(c[2], -1.5, 1e-12);
}

TEST(Basis, CentredPolynomialExpandsToTheSameInMu) {
  const Vec c = {0.3, -1.2, 0.7, 2.5, -0.4};
  const Vec m = centred_to_mu(c);
  for (double mu = 0; mu <= 1.0; mu += 0.03125)
    EXPECT_NEAR(eval_polynomial(m, mu), eval_polynomial(c, 2 * mu - 1), kRoundoff);
}

// The committed basis (data/basis/basis_functions.csv, src/fresnel/basis_polynomials.h): columns by
// name, one vector per column.
std::map<std::string, Vec> committed_functions() {
  const auto rows =
      test::csv_file_rows(std::string(FL_SOURCE_DIR) + "/data/basis/basis_functions.csv");
  std::map<std::string, Vec> columns;
  for (size_t i = 1; i < rows.size(); ++i)
    for (size_t c = 0; c < rows[0].size(); ++c)
      columns[rows[0][c]].push_back(std::stod(rows[i][c]));
  return columns;
}

std::string term_name(int k) {
  std::string name = "b";
  name += std::to_string(k);
  return name;
}

// The shipped functions are polynomials of the shipped degree: refitting them loses only rounding
// (docs/basis.md states 2e-14).
constexpr double kShippedFitTolerance = 1e-12;

TEST(CommittedBasis, FirstTermIsOne) {
  auto f = committed_functions();
  ASSERT_EQ(f["mu"].size(), 91u);
  for (size_t j = 0; j < 91; ++j) {
    EXPECT_EQ(f["b0"][j], 1.0);
    EXPECT_EQ(fresnel::basis_term(0, f["mu"][j]), 1.0);
  }
}

TEST(CommittedBasis, PolynomialsMatchTheSampledVectorsWithinTheStatedError) {
  auto f = committed_functions();
  for (int k = 1; k < fresnel::kBasisTerms; ++k) {
    const Vec& sampled = f[term_name(k)];
    ASSERT_EQ(sampled.size(), 91u);
    const double stated = fresnel::kBasisPolyMaxError[k - 1];
    EXPECT_LT(stated, kShippedFitTolerance);
    double worst = 0, sum2 = 0;
    for (size_t j = 0; j < 91; ++j) {
      const double mu = f["mu"][j], e = std::abs(fresnel::basis_term(k, mu) - sampled[j]);
      worst = std::max(worst, e);
      sum2 += e * e;
      // The polynomial in μ is the same polynomial.
      double p = 0;
      for (int i = fresnel::kBasisPolyDegree; i >= 0; --i)
        p = p * mu + fresnel::kBasisPolyMu[k - 1][i];
      EXPECT_NEAR(p, fresnel::basis_term(k, mu), 1e-9);
    }
    EXPECT_NEAR(worst, stated, 1e-12) << "b" << k;
    EXPECT_NEAR(std::sqrt(sum2 / 91), fresnel::kBasisPolyRmsError[k - 1], 1e-12) << "b" << k;
  }
}

TEST(CommittedBasis, SampledTermsAreOrthogonalAndNormalized) {
  auto f = committed_functions();
  std::vector<Vec> terms;
  for (int k = 0; k < fresnel::kBasisTerms; ++k) terms.push_back(f[term_name(k)]);
  for (int a = 1; a < fresnel::kBasisTerms; ++a) {
    double peak = 0;
    for (double v : terms[a])
      if (std::abs(v) > std::abs(peak)) peak = v;
    EXPECT_EQ(peak, 1.0) << "b" << a;
    for (int b = 0; b < a; ++b)
      EXPECT_NEAR(dot(terms[a], terms[b]), 0.0,
                  kRoundoff * std::sqrt(dot(terms[a], terms[a]) * dot(terms[b], terms[b])))
          << "b" << a << " · b" << b;
  }
}

// The shipped polynomials at the samples, as a shader evaluates them: orthogonal to 1 and to each
// other (the optimized functions are polynomials of the shipped degree, so the fit loses nothing).
TEST(CommittedBasis, PolynomialsAreOrthogonalAtTheSamples) {
  const Vec mu = basis_mu_samples(91);
  std::vector<Vec> terms(fresnel::kBasisTerms);
  for (int k = 0; k < fresnel::kBasisTerms; ++k)
    for (double m : mu) terms[k].push_back(fresnel::basis_term(k, m));
  for (int a = 1; a < fresnel::kBasisTerms; ++a)
    for (int b = 0; b < a; ++b) {
      const double cosine =
          dot(terms[a], terms[b]) / std::sqrt(dot(terms[a], terms[a]) * dot(terms[b], terms[b]));
      EXPECT_NEAR(cosine, 0.0, kRoundoff) << "b" << a << " · b" << b;
    }
}

// Kulla & Conty 2017's F_avg = 2∫₀¹ b(μ) μ dμ of each committed term by composite Simpson's rule
// (20000 intervals: error below 1e-12 for these polynomials).
TEST(CommittedBasis, HemisphericalAveragesMatchQuadrature) {
  constexpr int kIntervals = 20000;
  for (int k = 1; k < fresnel::kBasisTerms; ++k) {
    double s = 0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double mu = double(i) / kIntervals;
      const double w = (i == 0 || i == kIntervals) ? 1 : (i % 2 ? 4 : 2);
      s += w * fresnel::basis_term(k, mu) * mu;
    }
    EXPECT_NEAR(2 * s / (3.0 * kIntervals), fresnel::kBasisAverage[k - 1], 1e-10) << "b" << k;
  }
}

// fresnel::basis_coefficients (normal equations, Cholesky) against Projector (Eigen's QR) on
// gold-like and glass-like exact Fresnel curves.
TEST(CommittedBasis, CoefficientsMatchTheQrProjection) {
  const Vec mu = basis_mu_samples(91);
  for (const auto& [eta, kappa] : {std::pair{0.27, 2.95}, std::pair{1.5, 0.0}}) {
    Vec f;
    for (double m : mu)
      f.push_back(fresnel::fresnel_conductor(m, std::complex<double>(eta, kappa)));
    for (int terms = 2; terms <= fresnel::kBasisTerms; ++terms) {
      std::vector<Vec> functions(terms);
      for (int k = 0; k < terms; ++k)
        for (double m : mu) functions[k].push_back(fresnel::basis_term(k, m));
      const Vec expected = Projector(functions).coefficients(f);
      const auto c = fresnel::basis_coefficients(mu, f, terms);
      for (int k = 0; k < fresnel::kBasisTerms; ++k)
        EXPECT_NEAR(c[k], k < terms ? expected[k] : 0.0, 1e-10) << "K=" << terms << " c" << k;
    }
  }
}

}  // namespace
}  // namespace fl::analysis
