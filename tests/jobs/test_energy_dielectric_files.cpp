// `lut energy --dielectric` read back as an engine reads it: the EXR atlas decoded, each slice's
// tile sampled bilinearly at the documented uv, two slices mixed linearly in t = (F0/0.25)^¼, and
// the result compared with the Gauss–Legendre quadrature of the lobe with Fresnel's equations
// (dfg_reference.h; the Fresnel equations in their sine and tangent form, written here).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "dfg_reference.h"
#include "io/exr.h"
#include "jobs/lut_files.h"
#include "test_util.h"

namespace fl {
namespace {

// Midway between slices E_F departs from linear in t by ≤ 1.9e-3 outside (docs/engines.md), plus
// the table's sampling error at 4096 points per cell (measured 1.3e-3 on these cells); inside the
// critical angle moves with η (measured 3.8e-3 here; up to 0.054 midway between slices).
constexpr double kEngineReadTolerance = 3e-3;
constexpr double kEngineReadToleranceInside = 0.01;

// Born & Wolf §1.5.2: r_s = sin²(θi − θt)/sin²(θi + θt), r_p = tan²(θi − θt)/tan²(θi + θt).
double reference_fresnel(double cos_i, double eta) {
  const double theta_i = std::acos(std::clamp(cos_i, 0.0, 1.0));
  const double sin_t = std::sin(theta_i) / eta;
  if (sin_t >= 1.0) return 1.0;
  if (theta_i < 1e-7) return std::pow((eta - 1) / (eta + 1), 2);
  const double theta_t = std::asin(sin_t);
  const double rs = std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
  const double rp = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
  return 0.5 * (rs * rs + rp * rp);
}

// A GL texture read: bilinear between texel centres, clamp to edge.
double bilinear(const io::ExrImage& img, int channel, double u, double v) {
  const int c = static_cast<int>(img.channels.size());
  const double x = u * img.width - 0.5, y = v * img.height - 0.5;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto at = [&](int xi, int yi) {
    xi = std::clamp(xi, 0, img.width - 1), yi = std::clamp(yi, 0, img.height - 1);
    return static_cast<double>(
        img.pixels[(static_cast<size_t>(yi) * img.width + xi) * c + channel]);
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
         fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

// The atlas's shader (fresnelLab:shader) in C++: E_F (R) or, for η < 1, B.
double engine_read(const io::ExrImage& img, int n, int slices, double eta, double nov,
                   double roughness) {
  const int tiles = static_cast<int>(std::lround(std::sqrt(slices)));
  const double t = std::sqrt(std::abs(eta - 1) / ((eta + 1) * 0.5));
  const double s = std::clamp(t, 0.0, 1.0) * (slices - 1);
  const int k = std::min(static_cast<int>(s), slices - 2);
  auto read = [&](int slice) {
    const double su = nov * (n - 1) + 0.5, sv = roughness * (n - 1) + 0.5;
    const std::string name = eta >= 1 ? "R" : "B";
    const int channel = static_cast<int>(std::find(img.channels.begin(), img.channels.end(), name) -
                                         img.channels.begin());
    return bilinear(img, channel, ((slice % tiles) * n + su) / (tiles * n),
                    ((slice / tiles) * n + sv) / (tiles * n));
  };
  return read(k) + (s - k) * (read(k + 1) - read(k));
}

TEST(DielectricEnergyFiles, EngineReadMatchesQuadrature) {
  test::TempDir dir;
  jobs::LutRequest r;
  r.size = 8;
  r.samples = 4096;
  r.dielectric = true;
  r.out = dir.path() + "/d.exr";
  const auto o = jobs::dielectric_energy_lut(r);
  ASSERT_EQ(o.files.size(), 1u);
  std::ofstream(o.files[0].first, std::ios::binary) << o.files[0].second;
  const auto img = io::read_exr(o.files[0].first);
  ASSERT_EQ(img.width, 4 * r.size);
  ASSERT_EQ(img.channels.size(), 4u);
  double max_out = 0, max_in = 0;
  for (double eta : {1.33, 1.5, 2.4})
    for (int i : {2, 4, 7})
      for (int j : {1, 3, 6}) {
        const double nov = i / 7.0, roughness = j / 7.0, alpha = roughness * roughness;
        for (double e : {eta, 1 / eta}) {
          const double ref = test::reference_lobe_integrals(nov, alpha, [&](double voh) {
            return test::Values{reference_fresnel(voh, e), 0, 0, 0};
          })[0];
          const double d = std::abs(engine_read(img, r.size, r.slices, e, nov, roughness) - ref);
          (e >= 1 ? max_out : max_in) = std::max(e >= 1 ? max_out : max_in, d);
        }
      }
  std::printf("engine read of the atlas vs quadrature: max %.3g outside, %.3g inside\n", max_out,
              max_in);
  EXPECT_LT(max_out, kEngineReadTolerance);
  EXPECT_LT(max_in, kEngineReadToleranceInside);
}

}  // namespace
}  // namespace fl
