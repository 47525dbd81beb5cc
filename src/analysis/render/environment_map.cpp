// Environment maps: a latitude-longitude image's radiance and its luminance-proportional sampling,
// and the exposure of an image in the working space.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/render/render.h"
#include "util/errors.h"

namespace fl::analysis {
namespace {

using brdf::Vec3;

constexpr double kDegToRad = std::numbers::pi / 180.0;

}  // namespace

EnvironmentMap::EnvironmentMap(io::LatLongImage image, const color::Rgb& luminance,
                               double rotation_deg)
    : image_(std::move(image)), rotation_deg_(rotation_deg) {
  const int w = image_.width, h = image_.height;
  if (w < 1 || h < 1 || image_.rgb.size() != 3 * static_cast<size_t>(w) * h)
    throw std::invalid_argument("EnvironmentMap: image size and pixel count disagree");
  weight_.resize(static_cast<size_t>(w) * h);
  row_cdf_.assign(static_cast<size_t>(h) + 1, 0.0);
  column_cdf_.assign(static_cast<size_t>(w + 1) * h, 0.0);
  for (int y = 0; y < h; ++y) {
    const double sin_theta = std::sin(std::numbers::pi * (y + 0.5) / h);
    double* cdf = &column_cdf_[static_cast<size_t>(y) * (w + 1)];
    for (int x = 0; x < w; ++x) {
      const float* p = &image_.rgb[3 * (static_cast<size_t>(y) * w + x)];
      const double lum =
          std::max(0.0, luminance.r * p[0] + luminance.g * p[1] + luminance.b * p[2]);
      weight_[static_cast<size_t>(y) * w + x] = std::isfinite(lum) ? lum * sin_theta : 0.0;
      cdf[x + 1] = cdf[x] + weight_[static_cast<size_t>(y) * w + x];
    }
    row_cdf_[y + 1] = row_cdf_[y] + cdf[w];
    if (cdf[w] > 0)
      for (int x = 1; x <= w; ++x) cdf[x] /= cdf[w];
  }
  total_ = row_cdf_[h];
  if (total_ > 0)
    for (auto& c : row_cdf_) c /= total_;
}

void EnvironmentMap::direction_to_uv(const Vec3& d, double& u, double& v) const {
  const double longitude = std::atan2(d.x, d.z);
  u = 0.5 - (longitude - rotation_deg_ * kDegToRad) / (2.0 * std::numbers::pi);
  u -= std::floor(u);
  v = std::acos(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi;
}

Vec3 EnvironmentMap::uv_to_direction(double u, double v) const {
  const double longitude = std::numbers::pi * (1.0 - 2.0 * u) + rotation_deg_ * kDegToRad;
  const double theta = std::numbers::pi * v;
  return {std::sin(theta) * std::sin(longitude), std::cos(theta),
          std::sin(theta) * std::cos(longitude)};
}

color::Rgb EnvironmentMap::texel(int x, int y) const {
  const float* p = &image_.rgb[3 * (static_cast<size_t>(y) * image_.width + x)];
  return {p[0], p[1], p[2]};
}

color::Rgb EnvironmentMap::radiance(const Vec3& dir) const {
  double u = 0, v = 0;
  direction_to_uv(dir, u, v);
  return radiance_uv(u, v);
}

void EnvironmentMap::lookup(const Vec3& dir, color::Rgb& radiance, double& pdf) const {
  double u = 0, v = 0;
  direction_to_uv(dir, u, v);
  radiance = radiance_uv(u, v);
  pdf = pdf_uv(u, v, std::sqrt(std::max(0.0, 1.0 - dir.y * dir.y)));
}

color::Rgb EnvironmentMap::radiance_uv(double u, double v) const {
  const int w = image_.width, h = image_.height;
  const double fx = u * w - 0.5, fy = v * h - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double tx = fx - x0, ty = fy - y0;
  const auto wrap = [w](double x) {
    return static_cast<int>(((static_cast<long long>(x) % w) + w) % w);
  };
  const auto clamp_row = [h](double y) { return static_cast<int>(std::clamp(y, 0.0, h - 1.0)); };
  const int xa = wrap(x0), xb = wrap(x0 + 1), ya = clamp_row(y0), yb = clamp_row(y0 + 1);
  return color::lerp(color::lerp(texel(xa, ya), texel(xb, ya), tx),
                     color::lerp(texel(xa, yb), texel(xb, yb), tx), ty);
}

Vec3 EnvironmentMap::sample(double u1, double u2, double& pdf) const {
  pdf = 0;
  if (!can_sample()) return {0, 0, 1};
  const int w = image_.width, h = image_.height;
  const int y = std::clamp(
      static_cast<int>(std::upper_bound(row_cdf_.begin(), row_cdf_.end(), u2) - row_cdf_.begin()) -
          1,
      0, h - 1);
  const double* cdf = &column_cdf_[static_cast<size_t>(y) * (w + 1)];
  const int x =
      std::clamp(static_cast<int>(std::upper_bound(cdf, cdf + w + 1, u1) - cdf) - 1, 0, w - 1);
  const double dv = (u2 - row_cdf_[y]) / std::max(1e-300, row_cdf_[y + 1] - row_cdf_[y]);
  const double du = (u1 - cdf[x]) / std::max(1e-300, cdf[x + 1] - cdf[x]);
  const double u = (x + std::clamp(du, 0.0, 1.0)) / w, v = (y + std::clamp(dv, 0.0, 1.0)) / h;
  const Vec3 d = uv_to_direction(u, v);
  pdf = this->pdf(d);
  return d;
}

double EnvironmentMap::pdf(const Vec3& dir) const {
  double u = 0, v = 0;
  direction_to_uv(dir, u, v);
  return pdf_uv(u, v, std::sqrt(std::max(0.0, 1.0 - dir.y * dir.y)));
}

double EnvironmentMap::pdf_uv(double u, double v, double sin_theta) const {
  if (!can_sample() || sin_theta <= 0.0) return 0.0;
  const int w = image_.width, h = image_.height;
  const int x = std::min(w - 1, static_cast<int>(u * w)),
            y = std::min(h - 1, static_cast<int>(v * h));
  // Density in (u, v) is weight · w·h / Σ weight; dω = 2π² sin θ du dv.
  return weight_[static_cast<size_t>(y) * w + x] / total_ * w * h /
         (2.0 * std::numbers::pi * std::numbers::pi * sin_theta);
}

EnvironmentMap environment_map(const Context& ctx, io::LatLongImage image, const std::string& space,
                               double rotation_deg, double exposure_ev, double& scale) {
  const color::Mat3 m = ctx.spaces().conversion(space, ctx.settings().space);
  const auto& to_xyz = ctx.space().rgb_to_xyz;
  const color::Rgb luminance{to_xyz(1, 0), to_xyz(1, 1), to_xyz(1, 2)};
  double weighted = 0, solid_angle = 0;
  for (size_t k = 0; 3 * k + 2 < image.rgb.size(); ++k) {
    const auto o = m.apply<double>({image.rgb[3 * k], image.rgb[3 * k + 1], image.rgb[3 * k + 2]});
    for (int c = 0; c < 3; ++c) image.rgb[3 * k + c] = static_cast<float>(o[c]);
    const double sin_theta =
        std::sin(std::numbers::pi * (static_cast<double>(k / image.width) + 0.5) / image.height);
    weighted += sin_theta * (luminance.r * o[0] + luminance.g * o[1] + luminance.b * o[2]);
    solid_angle += sin_theta;
  }
  // A dark image cannot be exposed to a mean luminance: every render would be black, and ΔE2000
  // between black renders 0 whatever the model.
  if (!(weighted > 0) || !std::isfinite(weighted))
    throw InputError(fmt::format(
        "the environment's mean luminance in {} is {:g}, not a positive number: nothing to expose",
        ctx.settings().space, weighted / solid_angle));
  scale = std::exp2(exposure_ev) * solid_angle / weighted;
  for (auto& v : image.rgb) v = static_cast<float>(v * scale);
  return EnvironmentMap(std::move(image), luminance, rotation_deg);
}

}  // namespace fl::analysis
