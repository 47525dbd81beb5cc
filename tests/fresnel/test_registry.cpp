// Generic checks run over every model of the registry, so a model is tested the day it is added:
// batch against scalar, float against double, Ceres Jacobians against finite differences, the
// derivation on a spectrally flat material (whose ground truth is known in closed form) and domain
// edges. The table terms' declarations: test_table_terms.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"
#include "fit/fit.h"
#include "fresnel/batch.h"
#include "fresnel/derive.h"
#include "fresnel/exact.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "test_util.h"

namespace fl {
namespace {

using fresnel::ModelSpec;

using test::cosines;

// The batched kernel runs the same scalar code per element: bit-identical in double. In float the
// vectorized pow/sqrt of the batch may round differently from the scalar call by a few ulps.
constexpr double kFloatBatchRelative = 1e-5;
// Float kernels against double: float has 24 bits; the conductor equations lose a few more
// through cancellation near grazing incidence.
constexpr double kFloatVsDouble = 2e-5;

// The README's list of models (its "**Models** (`--model`)" item) names exactly the registry's.
TEST(Registry, ReadmeListsExactlyTheRegisteredModels) {
  std::ifstream in(std::string(FL_SOURCE_DIR) + "/README.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string readme = ss.str();
  const auto at = readme.find("- **Models** (`--model`):");
  ASSERT_NE(at, std::string::npos);
  const auto end = readme.find("\n- **", at + 1);
  const std::string item = readme.substr(at, end - at);
  std::set<std::string> listed, registered;
  const std::regex code("`([a-z0-9_]+)`");
  for (auto it = std::sregex_iterator(item.begin(), item.end(), code); it != std::sregex_iterator();
       ++it)
    if ((*it)[1] != "--model") listed.insert((*it)[1]);
  for (const auto& m : fresnel::model_specs()) registered.insert(m.name);
  EXPECT_EQ(listed, registered);
}

TEST(Registry, BatchMatchesScalarInDoubleAndFloat) {
  const auto cos_d = cosines(257);
  std::vector<float> cos_f(cos_d.begin(), cos_d.end());
  for (const auto& spec : fresnel::model_specs()) {
    const auto p = fresnel::example_params(spec.model);
    ASSERT_EQ(static_cast<int>(p.size()), spec.param_count()) << spec.name;
    const std::vector<float> pf(p.begin(), p.end());
    std::vector<double> out_d(3 * cos_d.size());
    std::vector<float> out_f(3 * cos_d.size());
    fresnel::evaluate_batch(spec.model, p.data(), cos_d.data(), cos_d.size(), out_d.data());
    fresnel::evaluate_batch(spec.model, pf.data(), cos_f.data(), cos_f.size(), out_f.data());
    for (size_t i = 0; i < cos_d.size(); ++i) {
      const auto sd = fresnel::evaluate_rgb(spec.model, cos_d[i], p.data());
      const auto sf = fresnel::evaluate_rgb(spec.model, cos_f[i], pf.data());
      for (int c = 0; c < 3; ++c) {
        const size_t k = c * cos_d.size() + i;
        EXPECT_EQ(out_d[k], sd[c]) << spec.name << " cos " << cos_d[i];
        EXPECT_NEAR(out_f[k], sf[c], kFloatBatchRelative * std::max(1.0f, std::abs(sf[c])))
            << spec.name;
        EXPECT_NEAR(sf[c], sd[c], kFloatVsDouble)
            << spec.name << " cos " << cos_d[i] << " channel " << c;
      }
    }
  }
}

// Every corner of the fit box (each parameter at its lower or upper bound, all 2^n combinations),
// at normal, intermediate and grazing incidence: finite values, and for models whose first channel
// parameter is F0, exactly F0 at normal incidence. Every bound of every parameter is visited.
TEST(Registry, FiniteAtTheCornersOfTheFitBox) {
  for (const auto& spec : fresnel::model_specs()) {
    const auto box = spec.bounds();
    const size_t n = box.size();
    ASSERT_LE(n, 16u);  // at most 65536 corners
    std::vector<std::array<bool, 2>> met(n, {false, false});
    for (unsigned corner = 0; corner < (1u << n); ++corner) {
      for (size_t i = 0; i < n; ++i) met[i][(corner >> i) & 1u] = true;
      std::vector<double> p(n);
      for (size_t i = 0; i < n; ++i) p[i] = (corner >> i) & 1u ? box[i].hi : box[i].lo;
      for (double c : {0.0, 1e-7, 1.0 / 7.0, 0.5, 1.0 - 1e-9, 1.0}) {
        const auto rgb = spec.evaluate(c, p.data(), false);
        for (int ch = 0; ch < 3; ++ch)
          EXPECT_TRUE(std::isfinite(rgb[ch])) << spec.name << " corner " << corner << " cos " << c;
      }
      if (std::string(spec.channel_params[0].name) == "f0") {
        // The formula itself: a kernel's output clamp (the F82 model's [0, 1]) would hide an F0 the
        // box allows outside [0, 1].
        const auto rgb = spec.evaluate(1.0, p.data(), true);
        for (int ch = 0; ch < 3; ++ch) {
          // F0 within its domain (Gulbrandsen's mapping is singular at 0 and 1 and holds r in
          // [1e-9, 0.99999]: hence the 2e-9 tolerance).
          const auto& dom = spec.channel_params[0].domain;
          EXPECT_NEAR(rgb[ch], std::clamp(p[ch * spec.per_channel()], dom.lo, dom.hi), 2e-9)
              << spec.name << " corner " << corner;
        }
      }
    }
    for (size_t i = 0; i < n; ++i)
      EXPECT_TRUE(met[i][0] && met[i][1]) << spec.name << " parameter " << i;
  }
}

TEST(Registry, ClampToDomainMovesOnlyOutsideValues) {
  for (const auto& spec : fresnel::model_specs()) {
    const auto domain = spec.domain();
    auto inside = fresnel::example_params(spec.model);
    EXPECT_EQ(fresnel::clamp_to_domain(spec.model, inside), 0) << spec.name;
    std::vector<double> far(inside.size(), -1e6);
    int bounded = 0;
    for (const auto& d : domain) bounded += d.lo > -fresnel::kUnbounded;
    EXPECT_EQ(fresnel::clamp_to_domain(spec.model, far), bounded) << spec.name;
    for (size_t i = 0; i < far.size(); ++i) EXPECT_GE(far[i], domain[i].lo) << spec.name;
  }
}

// A material whose η and κ do not depend on wavelength: its ground truth at every angle is the
// exact conductor reflectance R(θ) times the colour pipeline's response to a flat spectrum.
struct FlatMaterial {
  analysis::Context ctx{[] {
    analysis::Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  std::complex<double> ior;
  spectral::ComplexIorSpectrum spectrum;
  color::Rgb flat_response;  // RGB of the constant spectrum 1
  fresnel::DerivedParameters derived;

  explicit FlatMaterial(std::complex<double> n) : ior(n) {
    spectrum.grid = ctx.grid();
    spectrum.ior.assign(static_cast<size_t>(ctx.grid().count), ior);
    for (const auto& w : ctx.rgb_weights()) flat_response = flat_response + w;
    derived = fresnel::derive_parameters(ctx.rgb_weights(), ctx.space().rgb_to_xyz, spectrum, 1.0,
                                         fresnel::kDefaultPointSampleNm);
  }
  double truth(double cos_theta) const { return fresnel::fresnel_conductor(cos_theta, ior); }
  fresnel::DeriveInput input() const { return {derived, spectrum, 1.0, ctx.rgb_weights()}; }
};

// Every model's derived parameters reproduce a flat material's normal-incidence colour, and the
// models that hold the exact equations (RGB η, κ; Gulbrandsen's exact reparameterization)
// reproduce its whole curve. The basis models (coefficients, not reflectances, first) project the
// whole curve by least squares: at normal incidence they are within their residual, measured up to
// 3.0e-3 (basis3 on the flat metal; basis5 9.4e-6).
TEST(Registry, DerivationOnAFlatMaterialIsExactAtNormalIncidence) {
  constexpr double kProjectionAtNormalIncidence = 1e-2;
  for (const auto ior : {std::complex<double>(0.27, 2.9), std::complex<double>(1.5, 0.0),
                         std::complex<double>(2.8, 3.5)}) {
    const FlatMaterial m(ior);
    for (const auto& spec : fresnel::model_specs()) {
      const auto p = fresnel::derived_model_params(spec.model, m.input());
      const auto at0 = spec.evaluate(1.0, p.data(), false);
      const bool projection = spec.channel_params[0].kind == fresnel::ParamKind::Coefficient;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(at0[c], m.truth(1.0) * m.flat_response[c],
                    projection ? kProjectionAtNormalIncidence : 1e-9)
            << spec.name << " ior " << ior;
    }
    // RGB η, κ: processed as reflectances, a constant η, κ comes back scaled by the flat response.
    const auto eta_kappa =
        fresnel::derived_model_params(fresnel::model_of<fresnel::models::FresnelRgb>, m.input());
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(eta_kappa[2 * c], ior.real() * m.flat_response[c], 1e-9);
      EXPECT_NEAR(eta_kappa[2 * c + 1], ior.imag() * m.flat_response[c], 1e-9);
    }
  }
}

// Ceres' GradientChecker at several points around each model's gold fit. The finite differences
// are Ridders-extrapolated; the CIEDE2000 chain (cube roots, hue angles) keeps them to about 1e-6.
constexpr double kGradientTolerance = 1e-5;

TEST(Registry, JacobiansMatchFiniteDifferencesAtSeveralPoints) {
  analysis::Settings s;
  s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
  const analysis::Context ctx(s);
  const auto gold =
      analysis::load_material(ctx, spectral::resolve_material("gold", ctx.settings().paths));
  const auto truth = analysis::ground_truth_curve(ctx, gold.ior, 1.0);
  const auto target = analysis::curve_target(ctx, truth);
  const auto d = fresnel::derive_parameters(ctx.rgb_weights(), ctx.space().rgb_to_xyz, gold.ior,
                                            1.0, fresnel::kDefaultPointSampleNm);
  const fresnel::DeriveInput in{d, gold.ior, 1.0, ctx.rgb_weights(), ctx.cos_thetas(), truth};
  for (const auto& spec : fresnel::model_specs()) {
    const auto fitted =
        fit::fit_model(spec.model, target, fresnel::fit_starts(spec.model, in)).parameters;
    for (const double scale : {0.97, 0.995, 1.004}) {
      auto p = fitted;
      for (size_t i = 0; i < p.size(); ++i) p[i] *= i % 2 ? scale : 2.0 - scale;
      const auto check = fit::check_model_gradients(spec.model, target, p);
      EXPECT_TRUE(check.ok) << spec.name << ": " << check.report.substr(0, 2000);
      EXPECT_LT(check.max_relative_error, kGradientTolerance) << spec.name << " scale " << scale;
    }
  }
}

}  // namespace
}  // namespace fl
