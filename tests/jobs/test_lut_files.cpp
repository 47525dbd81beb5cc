// `lut dfg` files read back the way their renderers read them. The Filament layout: the .inc file
// decoded from its half-float bit patterns (IEEE 754 binary16, decoded here), sampled like a GL
// texture (bilinear, clamp to edge) at uv = (n·v, perceptual roughness), and Filament's shader
// formula mix(dfg.xxx, dfg.yyy, f0) against the brute-force integral of the same BRDF (GGX,
// height-correlated Smith, Schlick) by quadrature (dfg_reference.h). Its sheen channel against a
// quadrature of the Charlie lobe written from the papers. The split-sum CSV: F0·dfg1 + dfg2 against
// the same integral at the texel centres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/lut/lut.h"
#include "analysis/lut/lut_layout.h"
#include "csv_reader.h"
#include "dfg_reference.h"
#include "quadrature.h"
#include "test_util.h"

namespace fl {
namespace {

constexpr double kPi = std::numbers::pi;
// Filament's formula on the 128 × 128 table against the integral, n·v ≥ 0.05, within the span of
// the texel centres: measured 8.1e-4 with the 2048 samples per texel used here, 3.8e-4 with the
// default 8192 (at n·v = 0.05, where bilinear interpolation between texels dominates).
constexpr double kFilamentFormulaTolerance = 2e-3;
constexpr double kMinNov = 0.05;
// The sheen albedo (uniformly sampled half vectors) against quadrature, α ≥ 0.1.
constexpr double kSheenTolerance = 2e-3;
// Split-sum CSV values at the texel centres against the integral: sampling error only.
constexpr double kSplitSumTolerance = 1e-3;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// IEEE 754 binary16: 1 sign bit, 5 exponent bits (bias 15), 10 fraction bits.
double half_to_double(std::uint16_t h) {
  const int sign = h >> 15, exponent = (h >> 10) & 0x1f, fraction = h & 0x3ff;
  double v = exponent == 0 ? std::ldexp(fraction, -24) : std::ldexp(1024 + fraction, exponent - 25);
  if (exponent == 31) v = fraction ? NAN : INFINITY;
  return sign ? -v : v;
}

// The values of a Filament dfg.inc: every 0x.... token outside // comments.
std::vector<double> read_inc(const std::string& text) {
  std::vector<double> v;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("//", 0) == 0) continue;
    for (size_t p = line.find("0x"); p != std::string::npos; p = line.find("0x", p + 2))
      v.push_back(half_to_double(
          static_cast<std::uint16_t>(std::stoul(line.substr(p + 2, 4), nullptr, 16))));
  }
  return v;
}

// GL bilinear filtering with clamp-to-edge of an N × N RGB texture stored row by row (row 0 at v =
// 0).
std::array<double, 3> sample(const std::vector<double>& tex, int n, double u, double v) {
  auto axis = [n](double t, int& i0, int& i1, double& f) {
    const double x = t * n - 0.5;
    const double fl = std::floor(x);
    f = x - fl;
    i0 = std::clamp(static_cast<int>(fl), 0, n - 1);
    i1 = std::clamp(static_cast<int>(fl) + 1, 0, n - 1);
  };
  int x0, x1, y0, y1;
  double fx, fy;
  axis(u, x0, x1, fx);
  axis(v, y0, y1, fy);
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c) {
    auto at = [&](int x, int y) { return tex[(static_cast<size_t>(y) * n + x) * 3 + c]; };
    out[c] = (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) +
             fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
  }
  return out;
}

// Max |formula − integral| over a grid of (n·v, roughness) in [nov_lo, nov_hi] × [r_lo, r_hi], off
// the texel centres; the formula is linear in f0, so its largest error over f0 ∈ [0, 1] is at 0
// or 1.
struct Worst {
  double error = 0, nov = 0, rough = 0;
};
Worst formula_error(const std::vector<double>& tex, int n, double nov_lo, double nov_hi,
                    double r_lo, double r_hi, int points) {
  const int kPoints = points;
  Worst w;
  for (int a = 0; a < kPoints; ++a)
    for (int b = 0; b < kPoints; ++b) {
      const double nov = nov_lo + (nov_hi - nov_lo) * a / (kPoints - 1);
      const double rough = r_lo + (r_hi - r_lo) * b / (kPoints - 1);
      const auto dfg = sample(tex, n, nov, rough);
      const auto ref = test::reference_moments(nov, std::max(rough * rough, 1e-7));
      for (double f0 : {0.0, 1.0}) {
        const double formula = (1 - f0) * dfg[0] + f0 * dfg[1];  // mix(dfg.xxx, dfg.yyy, f0)
        const double integral = f0 * ref.dfg1 + ref.dfg2;        // ∫ (f0 + (1 − f0) Fc) ρ cos
        if (std::abs(formula - integral) > w.error) w = {std::abs(formula - integral), nov, rough};
      }
    }
  return w;
}

// Filament's lookup covers uv ∈ [½/N, 1 − ½/N] with its texel centres; beyond them (the outer half
// texel of each axis) clamp-to-edge holds the edge texel, which costs the slope there times ½/N
// whatever the table holds: 4.9e-3 at roughness 1, n·v = 1, where ∫ ρ cos falls by 1.2 per unit of
// roughness (the best constant would still be 2.4e-3 off). That strip is measured and bounded
// apart.
constexpr double kFilamentEdgeTolerance = 6e-3;

TEST(LutFiles, FilamentShaderFormulaMatchesTheIntegral) {
  test::TempDir tmp;
  const std::string inc = tmp.path() + "/dfg.inc";
  const auto r =
      test::run_command(std::string("'") + FL_CLI +
                        "' -q lut dfg --layout filament --samples 2048 --out '" + inc + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto tex = read_inc(slurp(inc));
  constexpr int n = 128;  // Filament's DFG_LUT_SIZE, the layout's default
  ASSERT_EQ(tex.size(), static_cast<size_t>(n * n * 3));
  const double lo = 0.5 / n, hi = 1 - 0.5 / n;
  const Worst inside = formula_error(tex, n, kMinNov, hi, lo, hi, 37);
  std::printf(
      "Filament formula on the 128x128 table vs integral, n.v in [%.2f, %.4f], roughness in [%.4f, "
      "%.4f]: "
      "max abs %.3g (n.v %.3f, roughness %.3f)\n",
      kMinNov, hi, lo, hi, inside.error, inside.nov, inside.rough);
  EXPECT_LE(inside.error, kFilamentFormulaTolerance);
  Worst edge;
  for (const Worst& w :
       {formula_error(tex, n, kMinNov, 1, hi, 1, 9), formula_error(tex, n, kMinNov, 1, 0, lo, 9),
        formula_error(tex, n, hi, 1, 0, 1, 9)})
    if (w.error > edge.error) edge = w;
  std::printf("  outer half texels (clamp to edge): max abs %.3g (n.v %.3f, roughness %.3f)\n",
              edge.error, edge.nov, edge.rough);
  EXPECT_LE(edge.error, kFilamentEdgeTolerance);
}

// Estevez & Kulla 2017, eq. 2, and Neubelt & Pettineo 2013, written here from the papers.
double sheen_reference(double nov, double alpha) {
  const brdf::Vec3 v{std::sqrt(1 - nov * nov), 0, nov};
  return test::integrate_sphere(
      [&](double x, double y, double z) {
        const brdf::Vec3 h = brdf::normalize(brdf::Vec3{x + v.x, y + v.y, z + v.z});
        const double sin2 = 1 - h.z * h.z;
        const double d = (2 + 1 / alpha) * std::pow(sin2, 0.5 / alpha) / (2 * kPi);
        const double vis = 1 / (4 * (z + nov - z * nov));
        return d * vis * z;
      },
      kPi / 2, 0.5);
}

TEST(LutFiles, SheenChannelMatchesQuadrature) {
  double worst = 0;
  for (double nov : {0.1, 0.4, 0.8, 1.0})
    for (double alpha : {0.1, 0.3, 0.6, 1.0}) {
      const double got = analysis::integrate_sheen_dfg(nov, alpha),
                   want = sheen_reference(nov, alpha);
      worst = std::max(worst, std::abs(got - want));
      EXPECT_NEAR(got, want, kSheenTolerance) << nov << " " << alpha;
    }
  std::printf("sheen albedo vs quadrature: max abs %.3g\n", worst);
}

TEST(LutFiles, SplitSumCsvCarriesItsFormulaAndReproducesTheIntegral) {
  test::TempDir tmp;
  const std::string csv = tmp.path() + "/dfg.csv";
  const auto r =
      test::run_command(std::string("'") + FL_CLI + "' -q lut dfg --size 8 --out '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = slurp(csv);
  int comments = 0, rows = 0;
  for (const auto& row : test::csv_rows(text)) comments += row[0].rfind("# ", 0) == 0;
  // Axes, channels and shader per texture of the table terms (dfg, dfg_2).
  EXPECT_EQ(comments, 3 * static_cast<int>(analysis::term_texture_names(true).size()));
  const auto table = test::csv_rows(text, {.skip_comments = true});
  ASSERT_FALSE(table.empty());
  test::CsvRow header{"nov", "perceptual_roughness", "alpha"};
  for (const auto& t : fresnel::kTermRegistry) header.push_back(t.dfg.channel);
  EXPECT_EQ(table[0], header);
  for (size_t i = 1; i < table.size(); ++i) {
    const auto c = test::csv_numbers(table[i]);
    ASSERT_EQ(c.size(), header.size());
    const auto ref = test::reference_moments(c[0], c[2]);
    for (double f0 : {0.04, 1.0})
      EXPECT_NEAR(f0 * c[3] + c[4], f0 * ref.dfg1 + ref.dfg2, kSplitSumTolerance);
    EXPECT_NEAR(c[5], ref.l_d, kSplitSumTolerance);
    ++rows;
  }
  EXPECT_EQ(rows, 64);
}

}  // namespace
}  // namespace fl
