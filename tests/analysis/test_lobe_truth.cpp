// The rendered error's truth (analysis/lut/rendered.h, lobe_truth: the spectral curve at the
// quadrature's nodes in cos θ) against the same lobe samples integrated two independent ways: with
// the spectral curve tabulated at 513 uniform values of cos θ and interpolated linearly (the brute
// force the quadrature replaced), and with the spectral curve at every sample.
#include <gtest/gtest.h>

#include <algorithm>

#include "analysis/lut/lut_accuracy.h"
#include "analysis/lut/rendered.h"
#include "analysis/pipeline/materials.h"

namespace fl::analysis {
namespace {

// Pages where the truth is hardest to interpolate: gases, whose curve turns within a few
// hundredths of cos θ of grazing (Xe is where the brute force is farthest from the converged
// integral), alkali metals with η < 1 (farthest from the quadrature), ice, high-index layered
// crystals and semiconductors, gold and an organic dye.
const std::vector<std::string> kHardPages{"main/Xe/nk/Borzsonyi",
                                          "main/He/nk/Borzsonyi",
                                          "main/O2/nk/Zhang",
                                          "main/Cs/nk/Smith",
                                          "main/Rb/nk/Smith",
                                          "main/H2O/nk/Kofman-10K",
                                          "main/PtSe2/nk/Tharrault-1L",
                                          "main/MoSe2/nk/Hsu-1L",
                                          "main/Ge/nk/Aspnes",
                                          "main/Au/nk/Johnson",
                                          "organic/C32H44N2O6 - SQIB/nk/Funke-alpha"};
// The rendered figures print three decimals: the quadrature may move none by more than a unit.
constexpr double kBruteForceBound = 1e-3;
// Against the spectral curve at every sample (measured over every database page: 2.2e-5, Cs).
constexpr double kConvergedBound = 5e-5;

Context test_context() {
  Settings settings;
  settings.paths = {FL_DEFAULT_DB, FL_MATERIALS};
  return Context(settings);
}

std::vector<LoadedMaterial> pages(const Context& ctx, const std::vector<std::string>& names) {
  LoadPolicy policy;
  policy.only = std::nullopt;
  policy.min_coverage = 0;
  auto set = load_materials(ctx, names, policy);
  EXPECT_EQ(set.materials.size(), names.size());
  return std::move(set.materials);
}

// lut-accuracy's points, narrower lobes and mirrors.
std::vector<ShadingPoint> test_points() {
  auto points = lut_accuracy_points();
  for (double r : {0.0, 0.02, 0.05, 0.1}) {
    auto more = shading_points({r});
    points.insert(points.end(), more.begin(), more.end());
  }
  return points;
}

// The lobe's mean of curve(v·h) over the samples (a mirror: curve(n·v)).
template <class Curve>
color::Rgb sampled_lobe(const ShadingPoint& p, const std::vector<brdf::DiskPoint>& disk,
                        Curve curve) {
  if (p.mirror) return curve(p.nov);
  color::Rgb sum{};
  for_each_lobe_sample(p.nov, p.alpha, disk,
                       [&](const LobeSample& s) { sum = sum + s.weight * curve(s.voh); });
  return (1.0 / kLutSamples) * sum;
}

TEST(LobeTruth, WithinAPrintedDigitOfTheBruteForce) {
  const auto ctx = test_context();
  const auto points = test_points();
  const auto disk = lobe_disk_points(kLutSamples);
  constexpr int kNodes = 513;
  for (const auto& m : pages(ctx, kHardPages)) {
    std::vector<color::Rgb> table(kNodes);
    for (int k = 0; k < kNodes; ++k)
      table[k] = ground_truth_rgb(ctx, m.ior, static_cast<double>(k) / (kNodes - 1), 1.0);
    const auto linear = [&](double mu) {
      const double x = std::clamp(mu, 0.0, 1.0) * (kNodes - 1);
      const int k = std::min(static_cast<int>(x), kNodes - 2);
      const double f = x - k;
      return (1.0 - f) * table[k] + f * table[k + 1];
    };
    const auto truth = lobe_truth(ctx, m, points);
    for (size_t i = 0; i < points.size(); ++i) {
      const auto brute = sampled_lobe(points[i], disk, linear);
      EXPECT_LE(color::ciede2000(ctx.rgb_to_lab(truth[i]), ctx.rgb_to_lab(brute)), kBruteForceBound)
          << m.material.name << " roughness " << points[i].roughness << " at " << points[i].view_deg
          << "°";
    }
  }
}

TEST(LobeTruth, WithinBoundOfTheSpectralCurveAtEverySample) {
  const auto ctx = test_context();
  std::vector<ShadingPoint> points = lut_accuracy_points();
  const auto narrow = shading_points({0.02});
  points.insert(points.end(), narrow.begin(), narrow.end());
  const auto disk = lobe_disk_points(kLutSamples);
  for (const auto& m :
       pages(ctx, {"main/Cs/nk/Smith", "main/Xe/nk/Borzsonyi", "main/H2O/nk/Kofman-10K"})) {
    const auto spectral = [&](double mu) {
      return ground_truth_rgb(ctx, m.ior, std::clamp(mu, 0.0, 1.0), 1.0);
    };
    const auto truth = lobe_truth(ctx, m, points);
    for (size_t i = 0; i < points.size(); ++i)
      EXPECT_LE(color::ciede2000(ctx.rgb_to_lab(truth[i]),
                                 ctx.rgb_to_lab(sampled_lobe(points[i], disk, spectral))),
                kConvergedBound)
          << m.material.name << " roughness " << points[i].roughness << " at " << points[i].view_deg
          << "°";
  }
}

}  // namespace
}  // namespace fl::analysis
