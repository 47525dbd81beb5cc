// The basis models (fresnel/models/basis.h) and the projection of any curve on the tables' terms
// (fresnel/projection.h), against independent sources: a curve built in the span from known
// coefficients, the normal equations' orthogonality, a Gauss–Legendre quadrature of the average,
// and the F82 unit's own table terms.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fresnel/exact.h"
#include "fresnel/projection.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "quadrature.h"

namespace fl::fresnel {
namespace {

// A least-squares solve on at most 5 well-conditioned terms loses a few digits of double.
constexpr double kRecoveryTolerance = 1e-10;
// Σ_j r_j·b_k(μ_j) relative to Σ_j |f_j·b_k(μ_j)|: the normal equations' rounding.
constexpr double kOrthogonalityTolerance = 1e-12;
// Gauss–Legendre with 24 nodes integrates the degree-11 integrands exactly, to rounding.
constexpr double kAverageTolerance = 1e-12;

// 91 angles uniform in θ, as the working grid.
std::vector<double> angles() {
  std::vector<double> mu;
  for (int j = 0; j <= 90; ++j) mu.push_back(std::cos(j * M_PI / 180.0));
  return mu;
}

// The derived parameters of basis model `m` for a given RGB curve at `mu`.
std::vector<double> derive_from(Model m, const std::vector<double>& mu,
                                const std::vector<color::Rgb>& truth) {
  const DerivedParameters d{};
  const spectral::ComplexIorSpectrum ior{};
  const DeriveInput in{d, ior, 1.0, {}, mu, truth};
  return derived_model_params(m, in);
}

// Gold at 550 nm (η = 0.43, κ = 2.46) and two other conductors, through the exact equations: curves
// outside every basis span.
std::vector<color::Rgb> conductor_curve(const std::vector<double>& mu) {
  std::vector<color::Rgb> out;
  for (double c : mu)
    out.push_back({fresnel_conductor(c, 0.18, 3.4), fresnel_conductor(c, 0.43, 2.46),
                   fresnel_conductor(c, 1.5, 1.9)});
  return out;
}

constexpr Model kBasisModels[] = {model_of<models::Basis<3>>, model_of<models::Basis<4>>,
                                  model_of<models::Basis<5>>};

TEST(BasisModels, ProjectionOfACurveInTheSpanRecoversItsCoefficients) {
  const auto mu = angles();
  for (Model m : kBasisModels) {
    const auto& spec = model_spec(m);
    const int k = spec.per_channel();
    std::vector<double> want;  // arbitrary coefficients, different per channel
    for (int ch = 0; ch < 3; ++ch)
      for (int i = 0; i < k; ++i) want.push_back(0.3 * (ch + 1) - 0.17 * i + 0.05 * i * i);
    std::vector<color::Rgb> truth;  // Σ c_k b_k(μ), each term from basis_term
    for (double c : mu) {
      color::Rgb rgb{};
      for (int ch = 0; ch < 3; ++ch)
        for (int i = 0; i < k; ++i) rgb[ch] += want[ch * k + i] * basis_term(i, c);
      truth.push_back(rgb);
    }
    const auto got = derive_from(m, mu, truth);
    ASSERT_EQ(got.size(), want.size()) << spec.name;
    for (size_t i = 0; i < want.size(); ++i)
      EXPECT_NEAR(got[i], want[i], kRecoveryTolerance) << spec.name << " " << i;
  }
}

TEST(BasisModels, ProjectionResidualIsOrthogonalToTheTerms) {
  const auto mu = angles();
  const auto truth = conductor_curve(mu);
  for (Model m : kBasisModels) {
    const auto& spec = model_spec(m);
    const int k = spec.per_channel();
    const auto p = derive_from(m, mu, truth);
    const auto fit = evaluate_curve(m, p, mu);
    for (int ch = 0; ch < 3; ++ch)
      for (int i = 0; i < k; ++i) {
        double dot = 0, scale = 0;
        for (size_t j = 0; j < mu.size(); ++j) {
          dot += (truth[j][ch] - fit[j][ch]) * basis_term(i, mu[j]);
          scale += std::abs(truth[j][ch] * basis_term(i, mu[j]));
        }
        EXPECT_LT(std::abs(dot) / scale, kOrthogonalityTolerance) << spec.name << " " << i;
      }
  }
}

// More terms never fit worse (nested least squares), and five fit the conductor curves closely.
TEST(BasisModels, MoreTermsFitNoWorse) {
  const auto mu = angles();
  const auto truth = conductor_curve(mu);
  double previous = 1e300;
  for (Model m : kBasisModels) {
    const auto fit = evaluate_curve(m, derive_from(m, mu, truth), mu);
    double sum2 = 0;
    for (size_t j = 0; j < mu.size(); ++j)
      for (int ch = 0; ch < 3; ++ch) sum2 += std::pow(truth[j][ch] - fit[j][ch], 2);
    const double rms = std::sqrt(sum2 / (3.0 * mu.size()));
    std::printf("%s: RMS residual %.3g on three conductor curves\n", model_spec(m).name, rms);
    EXPECT_LE(rms, previous * (1 + 1e-12));
    previous = rms;
  }
  EXPECT_LT(previous, 5e-3);
}

// The closed-form average c0 + Σ c_k·kBasisAverage against 2∫F μ dμ by quadrature.
TEST(BasisModels, ClosedFormAverageMatchesQuadrature) {
  const auto rule = test::gauss_legendre(24);
  for (Model m : kBasisModels) {
    const auto& spec = model_spec(m);
    const auto p = example_params(m);
    for (int ch = 0; ch < 3; ++ch) {
      const double got = spec.closed_form_average(p.data(), ch);
      double want = 0;  // Gauss–Legendre on [0, 1]: x = (t + 1)/2, dx = dt/2
      for (size_t k = 0; k < rule.x.size(); ++k) {
        const double x = 0.5 * (rule.x[k] + 1);
        want += 0.5 * rule.w[k] * 2.0 * x * evaluate_curve(m, p, {x})[0][ch];
      }
      EXPECT_NEAR(got, want, kAverageTolerance) << spec.name << " " << ch;
    }
  }
}

// Hoffman's span reproduces an F82 curve (its formula, unclamped) with the F82 unit's own weights.
TEST(Projection, HoffmanSpanRecoversTheF82TableTerms) {
  const auto mu = angles();
  const Model f82 = model_of<models::F82>;
  const auto p = example_params(f82);
  const auto curve = evaluate_curve_unclamped(f82, p, mu);
  for (int ch = 0; ch < 3; ++ch) {
    std::vector<double> f;
    for (const auto& rgb : curve) f.push_back(rgb[ch]);
    const auto got = project_on_terms(mu, f, kHoffmanSpan);
    const auto want = model_spec(f82).table_terms(p.data(), ch);
    for (const auto& t : kTermRegistry)
      EXPECT_NEAR(got[t.term], want[t.term], kRecoveryTolerance) << t.formula << " " << ch;
  }
}

}  // namespace
}  // namespace fl::fresnel
