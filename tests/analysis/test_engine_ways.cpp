// Every model rendered the three ways lut-accuracy shows (analysis/lut/rendered.h, EngineWay): at
// n·v, projected on Hoffman's span, projected on the basis.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/gold_shading.h"
#include "analysis/lut/lut_accuracy.h"
#include "fresnel/registry.h"

namespace fl::analysis {
namespace {

using fresnel::model_of;

// Projecting a curve that lies in the span returns its own weights up to the normal equations'
// rounding (condition number ~1e4 for the basis over 91 angles).
constexpr double kInSpan = 1e-6;
// Gulbrandsen's derived curve is within 0.07 ΔE2000 RMS of gold's ground truth; projected on the
// basis it should render within about that of the basis projection of the truth itself (basis5).
constexpr double kCurveGap = 0.1;

struct Gold : test::GoldShading {
  Gold()
      : GoldShading([] {
          StudyOptions o;
          o.fit = false;
          return o;
        }()) {}

  std::vector<double> de00(fresnel::Model m, Lighting l, EngineWay w) const {
    return rendered_de00(ctx, truth, m, study.result(m).derived, l, points, w);
  }
};

// Schlick's curve lies in Hoffman's span and basis3's in the basis: projected, they render exactly
// as their own shaders do.
TEST(EngineWays, CurvesInTheSpanRenderAsTheirOwnShader) {
  const Gold g;
  const auto schlick = model_of<fresnel::models::Schlick>;
  const auto basis3 = fresnel::model_from_name("basis3").model;
  for (const Lighting l : {Lighting::Ibl, Lighting::Area}) {
    const auto native = g.de00(schlick, l, EngineWay::Native);
    const auto hoffman = g.de00(schlick, l, EngineWay::HoffmanSpan);
    const auto b3 = g.de00(basis3, l, EngineWay::Native);
    const auto b3_projected = g.de00(basis3, l, EngineWay::BasisSpan);
    for (size_t k = 0; k < native.size(); ++k) {
      EXPECT_NEAR(hoffman[k], native[k], kInSpan) << lighting_name(l) << " point " << k;
      EXPECT_NEAR(b3_projected[k], b3[k], kInSpan) << lighting_name(l) << " point " << k;
    }
  }
}

// Pre-integrated models at n·v: Schlick's formula at n·v times the split sum's two channels read at
// the point (dfg1 integrates 1 − (1 − μ)⁵ and dfg2 (1 − μ)⁵, so together the lobe without Fresnel).
TEST(EngineWays, AtNdotVIsTheCurveTimesTheLobe) {
  const Gold g;
  const auto schlick = model_of<fresnel::models::Schlick>;
  const auto& p = g.study.result(schlick).derived;
  const auto de00 = g.de00(schlick, Lighting::Ibl, EngineWay::AtNdotV);
  for (size_t k = 0; k < g.points.size(); ++k) {
    const auto& pt = g.points[k];
    const double m = 1.0 - pt.nov, m5 = m * m * m * m * m;
    color::Rgb engine{};
    for (int c = 0; c < 3; ++c)
      engine[c] = (p[c] + (1.0 - p[c]) * m5) *
                  (pt.dfg[fresnel::Term::One] + pt.dfg[fresnel::Term::Schlick]);
    EXPECT_NEAR(de00[k], color::ciede2000(g.ctx.rgb_to_lab(g.truth[k]), g.ctx.rgb_to_lab(engine)),
                1e-9);
  }
}

// The point of the projection: Gulbrandsen's derived parameters on gold, about 3 ΔE2000 off at n·v,
// render as well as the truth's own basis projection once projected on the basis.
TEST(EngineWays, GulbrandsenProjectedOnTheBasisRendersAsItsCurve) {
  const Gold g;
  const auto gulbrandsen = model_of<fresnel::models::Gulbrandsen>;
  const auto basis5 = fresnel::model_from_name("basis5").model;
  for (const Lighting l : {Lighting::Ibl, Lighting::Area}) {
    const double at_nv = error_stats(g.de00(gulbrandsen, l, EngineWay::AtNdotV)).rms;
    const double projected = error_stats(g.de00(gulbrandsen, l, EngineWay::BasisSpan)).rms;
    const double truth_basis = error_stats(g.de00(basis5, l, EngineWay::Native)).rms;
    EXPECT_GT(at_nv, 2.0) << lighting_name(l);
    EXPECT_NEAR(projected, truth_basis, kCurveGap) << lighting_name(l);
  }
}

}  // namespace
}  // namespace fl::analysis
