// Generic checks of the table terms over every model of the registry and every term of the term
// registry: each term's kernel against its formula, each pre-integrable model's C++ weights against
// its kernel, and the truth of each model's pre-integration declaration (the channels it reads,
// the terms its GLSL weights name; the GLSL weights' values run on a driver in tests/vulkan).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>

#include "fresnel/registered_models.h"
#include "test_util.h"

namespace fl {
namespace {

using fresnel::ModelSpec;

using test::cosines;

// Parameter sets a generic check runs on: the unit's example and the middle of its fit box.
std::vector<std::vector<double>> probe_params(const ModelSpec& spec) {
  std::vector<double> mid;
  for (const auto& r : spec.bounds()) mid.push_back(0.5 * (r.lo + r.hi));
  return {fresnel::example_params(spec.model), mid};
}

// Each table term from its formula (TermSpec::formula), independently of fresnel::term_kernel:
// the basis terms b_k from the polynomials in μ (kBasisPolyMu, summed by powers in long double),
// where the kernel uses the centred ones by Horner's rule.
double term_formula(fresnel::Term t, double mu) {
  const std::string f = fresnel::term_spec(t).formula;
  if (f == "1") return 1.0;
  if (f == "(1 − μ)⁵") return std::pow(1 - mu, 5);
  if (f == "μ(1 − μ)⁶") return mu * std::pow(1 - mu, 6);
  for (int k = 1; k < fresnel::kBasisTerms; ++k) {
    if (f != "b" + std::to_string(k) + "(μ)") continue;
    long double sum = 0;
    for (int i = fresnel::kBasisPolyDegree; i >= 0; --i)
      sum = sum * mu + static_cast<long double>(fresnel::kBasisPolyMu[k - 1][i]);
    return static_cast<double>(sum);
  }
  ADD_FAILURE() << "no reference for the table term " << f;
  return 0;
}
// The two forms of a basis polynomial agree to rounding: the μ form's coefficients (up to 3.5e5)
// cancel to values of order 1, in long double to about 1e-13.
constexpr double kTermFormulaTolerance = 1e-10;

TEST(Registry, TableTermKernelsAreTheirFormulas) {
  for (const auto& t : fresnel::kTermRegistry)
    for (double mu : cosines(33)) {
      const double m = 1 - mu, m5 = m * m * m * m * m;
      EXPECT_NEAR(fresnel::term_kernel(t.term, mu, m, m5), term_formula(t.term, mu),
                  kTermFormulaTolerance)
          << t.formula;
      const double less = t.dfg.less == t.term ? 0.0 : term_formula(t.dfg.less, mu);
      EXPECT_NEAR(fresnel::dfg_kernel(t.term, mu, m, m5), term_formula(t.term, mu) - less,
                  kTermFormulaTolerance)
          << t.formula;
    }
}

// A pre-integrated model reads the channels of every table term it weighs (at its example and
// mid-box parameters): under IBL the term's DFG channel and the one it is stored less of, under
// area lights its LTC moment.
TEST(Registry, PreIntegratedModelsDeclareTheChannelsOfTheirTerms) {
  auto declares = [](const fresnel::LightingSupport& s, const char* channel) {
    return std::any_of(s.channels.begin(), s.channels.end(),
                       [&](const char* c) { return std::string(c) == channel; });
  };
  for (const auto& spec : fresnel::model_specs()) {
    const auto& pi = spec.pre_integration;
    if (!pi.ibl.fresnel_pre_integrated) continue;
    for (const auto& p : probe_params(spec))
      for (int c = 0; c < 3; ++c) {
        const auto w = spec.table_terms(p.data(), c);
        for (const auto& t : fresnel::kTermRegistry) {
          if (w[t.term] == 0.0) continue;
          EXPECT_TRUE(declares(pi.ibl, t.dfg.channel)) << spec.name << " " << t.dfg.channel;
          EXPECT_TRUE(declares(pi.ibl, fresnel::term_spec(t.dfg.less).dfg.channel)) << spec.name;
          EXPECT_TRUE(declares(pi.area, t.ltc.channel)) << spec.name << " " << t.ltc.channel;
        }
      }
  }
}

// A pre-integrated model's table terms are its formula: Σ_t w_t·term_t(μ) against the unclamped
// kernel at 65 angles; and every declaration has the code an engine needs for it.
TEST(Registry, TableTermsReproduceTheKernelAndShaderCodeMatchesTheDeclarations) {
  // The basis terms' references (term_formula) are within kTermFormulaTolerance of their kernels.
  constexpr double kTermsTolerance = kTermFormulaTolerance;
  for (const auto& spec : fresnel::model_specs()) {
    const auto& pi = spec.pre_integration;
    EXPECT_TRUE(pi.punctual.channels.empty()) << spec.name;
    EXPECT_EQ(std::string(pi.punctual.evaluated_at), "v·h") << spec.name;
    const bool pre = pi.ibl.fresnel_pre_integrated;
    // The emitter writes the table functions (and the punctual one where the unit gives none)
    // from the GLSL weights.
    EXPECT_EQ(!spec.term_weights.empty(), pre) << spec.name;
    EXPECT_TRUE(pre || !std::string(spec.shader.body).empty()) << spec.name;
    EXPECT_EQ(spec.table_terms != nullptr, pre) << spec.name;
    if (!pre) continue;
    // The GLSL weights name exactly the terms the C++ weights use (their values: the Vulkan tests).
    for (const auto& p : probe_params(spec))
      for (int c = 0; c < 3; ++c) {
        const auto w = spec.table_terms(p.data(), c);
        for (const auto& t : fresnel::kTermRegistry) {
          const bool glsl = std::any_of(spec.term_weights.begin(), spec.term_weights.end(),
                                        [&](const auto& tw) { return tw.term == t.term; });
          if (w[t.term] != 0.0) EXPECT_TRUE(glsl) << spec.name << " " << t.formula;
        }
      }
    for (const auto& p : probe_params(spec)) {
      for (double mu : cosines(65)) {
        const auto f = fresnel::evaluate_curve_unclamped(spec.model, p, {mu})[0];
        for (int c = 0; c < 3; ++c) {
          const auto w = spec.table_terms(p.data(), c);
          double sum = 0;  // Σ_t w_t·term_t(μ), each term written here from its formula
          for (const auto& t : fresnel::kTermRegistry) sum += w[t.term] * term_formula(t.term, mu);
          EXPECT_NEAR(sum, f[c], kTermsTolerance) << spec.name << " mu " << mu;
        }
      }
    }
  }
}

// A model is pre-integrable into the split-sum and LTC tables exactly when, per channel, it is a
// combination Σ_t w_t·term_t of the tables' terms (fresnel::kTermRegistry, each written here from
// its formula); it needs a term's channels exactly when w_t ≠ 0. Fitted here by least squares at
// 64 angles (normal equations by Gaussian elimination with partial pivoting); the residual shows
// whether the declaration holds.
struct SpanFit {
  double residual = 0;
  fresnel::TermValues weight_abs;
};
SpanFit fit_span(const ModelSpec& spec, const std::vector<double>& p, int channel) {
  constexpr int n = static_cast<int>(fresnel::kTermCount);
  const auto mu = cosines(64);
  std::vector<std::array<double, n>> a;
  std::vector<double> y;
  double ata[n][n + 1] = {};  // [AᵀA | Aᵀy]
  for (double u : mu) {
    a.emplace_back();
    for (int t = 0; t < n; ++t) a.back()[t] = term_formula(fresnel::kTermRegistry[t].term, u);
    y.push_back(spec.evaluate(u, p.data(), false)[channel]);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) ata[r][c] += a.back()[r] * a.back()[c];
      ata[r][n] += a.back()[r] * y.back();
    }
  }
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    for (int r = k + 1; r < n; ++r)
      if (std::abs(ata[r][k]) > std::abs(ata[pivot][k])) pivot = r;
    for (int c = 0; c <= n; ++c) std::swap(ata[k][c], ata[pivot][c]);
    for (int r = k + 1; r < n; ++r) {
      const double f = ata[r][k] / ata[k][k];
      for (int c = k; c <= n; ++c) ata[r][c] -= f * ata[k][c];
    }
  }
  double x[n];
  for (int r = n - 1; r >= 0; --r) {
    double v = ata[r][n];
    for (int c = r + 1; c < n; ++c) v -= ata[r][c] * x[c];
    x[r] = v / ata[r][r];
  }
  SpanFit out;
  for (size_t i = 0; i < mu.size(); ++i) {
    double f = 0;
    for (int t = 0; t < n; ++t) f += x[t] * a[i][t];
    out.residual = std::max(out.residual, std::abs(f - y[i]));
  }
  for (int t = 0; t < n; ++t) out.weight_abs.v[t] = std::abs(x[t]);
  return out;
}

bool lists(const fresnel::LightingSupport& s, const char* channel) {
  for (const char* c : s.channels)
    if (std::string(c) == channel) return true;
  return false;
}

TEST(Registry, PreIntegrationDeclarationsAreTrue) {
  namespace ch = fresnel::lut_channel;
  // A term's weight counts as used above this (the least-squares weights of terms a curve does
  // not use come out at rounding level, below 1e-10).
  constexpr double kUsedWeight = 1e-7;
  std::set<std::string> known{ch::kLtcMatrix};
  for (const auto& t : fresnel::kTermRegistry) known.insert({t.dfg.channel, t.ltc.channel});
  for (const auto& spec : fresnel::model_specs()) {
    const auto& pi = spec.pre_integration;
    for (const auto* s : {&pi.ibl, &pi.area}) {
      for (const char* c : s->channels) EXPECT_TRUE(known.count(c)) << spec.name << ": " << c;
      EXPECT_EQ(s->fresnel_pre_integrated, std::string(s->evaluated_at).empty()) << spec.name;
    }
    EXPECT_TRUE(lists(pi.ibl, ch::kDfgScale) && lists(pi.ibl, ch::kDfgBias)) << spec.name;
    EXPECT_TRUE(lists(pi.area, ch::kLtcMatrix) && lists(pi.area, ch::kLtcNorm)) << spec.name;
    // Two parameter sets: the unit's example and the middle of its fit box. A declared
    // pre-integrable model must be in the span for both; a model declared not pre-integrable
    // must leave it for at least one (Lazányi with α = 6 is the F82 model, in the span).
    std::vector<double> mid;
    for (const auto& r : spec.bounds()) mid.push_back(0.5 * (r.lo + r.hi));
    double worst = 0;
    fresnel::TermValues used;  // the largest weight of each term
    for (const auto& p : {fresnel::example_params(spec.model), mid}) {
      if (fresnel::output_clamped(spec.model, p, cosines(64))) continue;
      for (int c = 0; c < 3; ++c) {
        const auto f = fit_span(spec, p, c);
        worst = std::max(worst, f.residual);
        if (!pi.ibl.fresnel_pre_integrated) continue;
        EXPECT_LT(f.residual, 1e-12)
            << spec.name << ": declared pre-integrable but not in the tables' span";
        for (size_t t = 0; t < fresnel::kTermCount; ++t)
          used.v[t] = std::max(used.v[t], f.weight_abs.v[t]);
      }
    }
    EXPECT_EQ(pi.ibl.fresnel_pre_integrated, pi.area.fresnel_pre_integrated) << spec.name;
    if (!pi.ibl.fresnel_pre_integrated) {
      EXPECT_GT(worst, 1e-6) << spec.name
                             << ": declared not pre-integrable, but the tables' span holds it";
      continue;
    }
    // Each term's channels are listed exactly when the model uses the term (the term 1's always:
    // the lobe's integral); under IBL also the channel of the term it is stored less of.
    fresnel::TermValues needed;
    for (const auto& t : fresnel::kTermRegistry)
      if (used[t.term] > kUsedWeight || t.term == fresnel::Term::One) needed[t.term] = 1;
    for (const auto& t : fresnel::kTermRegistry) {
      bool dfg = needed[t.term] != 0;
      for (const auto& u : fresnel::kTermRegistry)
        dfg = dfg || (needed[u.term] != 0 && u.dfg.less == t.term);
      EXPECT_EQ(lists(pi.ibl, t.dfg.channel), dfg) << spec.name << " " << t.dfg.channel;
      EXPECT_EQ(lists(pi.area, t.ltc.channel), needed[t.term] != 0)
          << spec.name << " " << t.ltc.channel;
    }
  }
}

}  // namespace
}  // namespace fl
