// Environment maps: orientation against OpenEXR's own latitude-longitude functions, the sampling
// density against pixel weights written here, importance-sampled shading against quadrature, the
// colour conversion against the published Rec.709 → ACEScg matrix, exposure, and where the heat
// map statistics put pixels.
#include <OpenEXR/ImfEnvmap.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/render/render.h"
#include "color/rgb_space.h"
#include "quadrature.h"
#include "util/errors.h"

namespace fl {
namespace {

using analysis::EnvironmentMap;
using brdf::Vec3;
using io::LatLongImage;

constexpr double kPi = std::numbers::pi;
// Directions agree to float precision (OpenEXR computes in float).
constexpr double kDirectionTol = 1e-5;
// 4096 Hammersley samples per strategy against a midpoint quadrature of the same integral (the
// analytic environment's bound in test_pictures, relative to the radiance here).
constexpr int kShadingSamples = 4096;
constexpr double kShadingRelTol = 3e-3;
// ACES S-2014-004's AP1 luminance row and the Rec.709 → ACEScg (Bradford) matrix's first column as
// published (colour-science, ACES documentation), 4 decimals.
constexpr double kPublishedTol = 2e-4;

LatLongImage image(int w, int h, const std::function<color::Rgb(int, int)>& f) {
  LatLongImage img{w, h, std::vector<float>(3 * static_cast<size_t>(w) * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto c = f(x, y);
      float* p = &img.rgb[3 * (static_cast<size_t>(y) * w + x)];
      p[0] = static_cast<float>(c.r), p[1] = static_cast<float>(c.g),
      p[2] = static_cast<float>(c.b);
    }
  return img;
}

const color::Rgb kLuminance{0.2722287, 0.6740818, 0.0536895};  // AP1's Y row

// A map with structure: a smooth sky gradient and a bright 3 × 2 pixel "sun".
LatLongImage test_sky(int w, int h) {
  return image(w, h, [&](int x, int y) {
    if (x >= w / 3 && x < w / 3 + 3 && y >= h / 4 && y < h / 4 + 2) return color::Rgb{40, 30, 20};
    const double t = (y + 0.5) / h;
    return color::Rgb{0.2 + 0.6 * t, 0.3 + 0.3 * t,
                      0.9 - 0.5 * t + 0.1 * std::sin(2 * kPi * x / w)};
  });
}

// The default environment is a neutral studio: its mean radiance over every direction, and over
// the upper hemisphere a sphere reflects above its horizon, has the chromaticity of the working
// space's white. ACEScg's primaries and its white (D60, x 0.32168, y 0.33767) are those published
// in ACES S-2014-004; a tinted sky (a blue zenith of an outdoor scene) would put
// the mean off white, and gold reflecting it olive.
TEST(Environment, DefaultIsANeutralStudio) {
  constexpr double kChromaticityTol = 1e-3;  // a third of a just-noticeable step of white
  const auto env = analysis::default_environment();
  const auto to_xyz = color::rgb_to_xyz_from_primaries({0.713, 0.293}, {0.165, 0.830},
                                                       {0.128, 0.044}, {0.32168, 0.33767});
  for (const double theta_end : {kPi, kPi / 2}) {
    double mean[3];
    for (int c = 0; c < 3; ++c)
      mean[c] = test::integrate_sphere(
          [&](double x, double y, double z) {
            const auto l = analysis::environment_radiance(env, Vec3{x, z, y});  // quadrature z: up
            return c == 0 ? l.r : c == 1 ? l.g : l.b;
          },
          theta_end);
    const auto xyz = to_xyz * color::Rgb{mean[0], mean[1], mean[2]};
    const double sum = xyz.X + xyz.Y + xyz.Z;
    EXPECT_GT(mean[1], 0.1 * theta_end) << theta_end;  // lit, not black
    EXPECT_NEAR(xyz.X / sum, 0.32168, kChromaticityTol) << theta_end;
    EXPECT_NEAR(xyz.Y / sum, 0.33767, kChromaticityTol) << theta_end;
  }
}

TEST(Environment, OrientationIsOpenExrsLatLongMap) {
  const int w = 64, h = 32;
  const EnvironmentMap map(image(w, h, [](int, int) { return color::Rgb{1, 1, 1}; }), kLuminance);
  const Imath::Box2i dw({0, 0}, {w - 1, h - 1});
  for (double px : {0.0, 5.5, 16.0, 31.5, 40.25, 63.0})
    for (double py : {0.5, 8.0, 15.5, 24.75, 31.0}) {
      // OpenEXR puts pixel centres at the ends of the ranges: pixel position p ↔ u = p / (w − 1).
      const Imath::V3f d =
          Imf::LatLongMap::direction(dw, Imath::V2f(float(px), float(py))).normalized();
      const Vec3 ours = map.uv_to_direction(px / (w - 1), py / (h - 1));
      EXPECT_NEAR(ours.x, d.x, kDirectionTol) << px << "," << py;
      EXPECT_NEAR(ours.y, d.y, kDirectionTol) << px << "," << py;
      EXPECT_NEAR(ours.z, d.z, kDirectionTol) << px << "," << py;
      double u = 0, v = 0;
      map.direction_to_uv({d.x, d.y, d.z}, u, v);
      const Imath::V2f p = Imf::LatLongMap::pixelPosition(dw, d);
      EXPECT_NEAR(std::remainder(u * (w - 1) - p.x, double(w - 1)), 0.0, 1e-3);  // longitude wraps
      EXPECT_NEAR(v * (h - 1), p.y, 1e-3);
    }
  // The rotation turns the map about +y: 90° brings what was at +z to +x.
  const EnvironmentMap turned(image(w, h,
                                    [](int, int) {
                                      return color::Rgb{1, 1, 1};
                                    }),
                              kLuminance, 90.0);
  const Vec3 d = turned.uv_to_direction(0.5, 0.5);
  EXPECT_NEAR(d.x, 1.0, kDirectionTol);
  EXPECT_NEAR(d.z, 0.0, kDirectionTol);
}

TEST(Environment, SamplesFollowLuminanceTimesSolidAngle) {
  const int w = 16, h = 8;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const auto img = image(w, h, [&](int x, int y) {
    if ((x + y) % 5 == 0) return color::Rgb{0, 0, 0};  // black pixels are never drawn
    return color::Rgb{uni(rng), uni(rng), uni(rng)};
  });
  std::vector<double> expected(static_cast<size_t>(w) * h);
  double total = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = &img.rgb[3 * (static_cast<size_t>(y) * w + x)];
      const double lum = kLuminance.r * p[0] + kLuminance.g * p[1] + kLuminance.b * p[2];
      total += expected[static_cast<size_t>(y) * w + x] = lum * std::sin(kPi * (y + 0.5) / h);
    }
  const EnvironmentMap map(img, kLuminance);
  constexpr std::uint32_t kN = 1u << 16;
  std::vector<double> hits(expected.size(), 0.0);
  for (std::uint32_t i = 0; i < kN; ++i) {
    const auto p = brdf::hammersley(i, kN);
    double pdf = 0;
    const Vec3 d = map.sample(p.u1, p.u2, pdf);
    ASSERT_GT(pdf, 0.0);
    EXPECT_NEAR(pdf, map.pdf(d), 1e-9 * pdf);
    double u = 0, v = 0;
    map.direction_to_uv(d, u, v);
    hits[static_cast<size_t>(std::min(h - 1, int(v * h))) * w + std::min(w - 1, int(u * w))] +=
        1.0 / kN;
  }
  for (size_t k = 0; k < hits.size(); ++k) {
    EXPECT_NEAR(hits[k], expected[k] / total, 2e-3) << "pixel " << k;
    if (expected[k] == 0) {
      EXPECT_EQ(hits[k], 0.0);
    }
  }
}

// ∫ D V (n·l) L(l) dω over the hemisphere around n = +z by a midpoint rule in (θ, φ), L the map's
// red channel (F ≡ 1).
double quadrature(const EnvironmentMap& map, const Vec3& v, double alpha) {
  constexpr int kTheta = 900, kPhi = 720;
  double sum = 0;
  for (int i = 0; i < kTheta; ++i) {
    const double th = (i + 0.5) * (0.5 * kPi / kTheta);
    for (int j = 0; j < kPhi; ++j) {
      const double ph = (j + 0.5) * (2.0 * kPi / kPhi);
      const Vec3 l{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      sum += brdf::ggx_lobe_cos(v, l, alpha) * map.radiance(l).r * std::sin(th);
    }
  }
  return sum * (0.5 * kPi / kTheta) * (2.0 * kPi / kPhi);
}

TEST(Environment, ImportanceSampledShadingMatchesQuadrature) {
  const analysis::FresnelTable one = analysis::tabulate_fresnel(
      [](double) {
        return color::Rgb{1, 1, 1};
      },
      2);
  const analysis::SceneLight light = EnvironmentMap(test_sky(64, 32), kLuminance, 30.0);
  const auto& map = std::get<EnvironmentMap>(light);
  for (const double roughness : {0.25, 0.5})
    for (const Vec3 v : {Vec3{0, 0, 1}, brdf::normalize(Vec3{0.4, -0.3, 1.0})}) {
      const double alpha = roughness * roughness;
      const double ref = quadrature(map, v, alpha);
      const double shaded =
          analysis::shade_specular(light, one, {0, 0, 1}, v, alpha, kShadingSamples).r;
      EXPECT_NEAR(shaded, ref, kShadingRelTol * ref) << "roughness " << roughness;
    }
  // A constant map is a white furnace: the lobe's directional albedo, below 1.
  const analysis::SceneLight white = EnvironmentMap(image(32, 16,
                                                          [](int, int) {
                                                            return color::Rgb{1, 1, 1};
                                                          }),
                                                    kLuminance);
  const double albedo =
      analysis::shade_specular(white, one, {0, 0, 1}, {0, 0, 1}, 0.09, kShadingSamples).r;
  EXPECT_NEAR(albedo, quadrature(std::get<EnvironmentMap>(white), {0, 0, 1}, 0.09), kShadingRelTol);
  EXPECT_LT(albedo, 1.0);
}

TEST(Environment, MirrorSphereShowsPlusXOnItsRight) {
  // Bright only near longitude +π/2 on the horizon (u = 1/4): a mirror sphere shows it where the
  // normal halves the view (+z) and +x, at image point (sin 45°, 0).
  const int w = 64, h = 32;
  const analysis::SceneLight light =
      EnvironmentMap(image(w, h,
                           [&](int x, int y) {
                             const bool spot = std::abs(x + 0.5 - w / 4.0) < 1.0 &&
                                               std::abs(y + 0.5 - h / 2.0) < 1.0;
                             return spot ? color::Rgb{10, 10, 10} : color::Rgb{0, 0, 0};
                           }),
                     kLuminance);
  analysis::RenderSettings rs;
  rs.size_px = 221;
  rs.roughness = 0.0;
  const auto img = analysis::render_sphere(light,
                                           analysis::tabulate_fresnel(
                                               [](double) {
                                                 return color::Rgb{1, 1, 1};
                                               },
                                               2),
                                           rs);
  size_t best = 0;
  for (size_t k = 0; k < img.alpha.size(); ++k)
    if (img.rgb[3 * k] > img.rgb[3 * best]) best = k;
  const double per_px = 2.2 / rs.size_px;  // the frame spans [−1.1, 1.1]
  const double X = (static_cast<double>(best % rs.size_px) + 0.5 - rs.size_px / 2.0) * per_px;
  const double Y = (rs.size_px / 2.0 - static_cast<double>(best / rs.size_px) - 0.5) * per_px;
  EXPECT_NEAR(X, std::sin(kPi / 4), 0.03);
  EXPECT_NEAR(Y, 0.0, 0.03);
}

analysis::Settings ctx_settings() {
  analysis::Settings s;
  s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
  return s;
}

TEST(Environment, Rec709IsConvertedToAcescgAndExposed) {
  const analysis::Context ctx(ctx_settings());
  for (const double ev : {0.0, -1.5}) {
    double scale = 0;
    // Pure Rec.709 red, brighter towards the ground and varying round the horizon.
    const auto red = image(128, 64, [](int x, int y) {
      const double k = 1.0 + 3.0 * (y + 0.5) / 64 + 0.5 * std::cos(2 * kPi * (x + 0.5) / 128);
      return color::Rgb{k, 0, 0};
    });
    const auto map = analysis::environment_map(ctx, red, "lin_rec709", 0.0, ev, scale);
    const color::Rgb c = map.radiance({0.3, 0.5, std::sqrt(1 - 0.34)});
    // Published Rec.709 → ACEScg first column: 0.6131, 0.0702, 0.0206 (ratios to the red).
    EXPECT_NEAR(c.g / c.r, 0.0701937 / 0.6130974, kPublishedTol);
    EXPECT_NEAR(c.b / c.r, 0.0206156 / 0.6130974, kPublishedTol);
    // Exposure: the mean luminance over the sphere of directions (Gauss quadrature) is 2^ev.
    const double mean = test::integrate_sphere(
                            [&](double x, double y, double z) {
                              const auto r = map.radiance({x, y, z});
                              return kLuminance.r * r.r + kLuminance.g * r.g + kLuminance.b * r.b;
                            },
                            kPi, 0.5) /
                        (4 * kPi);
    EXPECT_NEAR(mean, std::exp2(ev), 1e-3 * std::exp2(ev));
  }
}

// A map without light cannot be exposed to a mean luminance: refused, not rendered black.
TEST(Environment, ABlackMapIsRefused) {
  const analysis::Context ctx(ctx_settings());
  double scale = 0;
  const auto black = image(16, 8, [](int, int) { return color::Rgb{0, 0, 0}; });
  try {
    analysis::environment_map(ctx, black, "lin_rec709", 0.0, 0.0, scale);
    FAIL() << "a black environment was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "the environment's mean luminance in acescg is 0, not a positive number: nothing "
                 "to expose");
  }
}

TEST(Environment, HeatmapStatsBandsFollowTheViewAngle) {
  const int n = 201;
  std::vector<double> de(static_cast<size_t>(n) * n, std::nan(""));
  const double per_px = 2.2 / n;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double X = (x + 0.5 - n / 2.0) * per_px, Y = (n / 2.0 - y - 0.5) * per_px,
                   r = std::hypot(X, Y);
      if (r >= 1) continue;
      // sin θ = r on the sphere: θ < 30° inside r = 0.5, θ ≥ 80° outside r = sin 80°.
      de[static_cast<size_t>(y) * n + x] =
          r < 0.5
              ? 1.0
              : (r < std::sin(60 * kPi / 180) ? 2.0 : (r < std::sin(80 * kPi / 180) ? 3.0 : 4.0));
    }
  const auto st = analysis::heatmap_stats(de, n, n);
  ASSERT_EQ(st.band_mean.size(), 4u);
  EXPECT_NEAR(st.band_mean[0], 1.0, 1e-9);
  EXPECT_NEAR(st.band_mean[1], 2.0, 0.02);  // a band edge can fall within a pixel's rounding
  EXPECT_NEAR(st.band_mean[2], 3.0, 0.02);
  EXPECT_NEAR(st.band_mean[3], 4.0, 0.02);
  EXPECT_DOUBLE_EQ(st.max, 4.0);
}

}  // namespace
}  // namespace fl
