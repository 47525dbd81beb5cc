#include "analysis/render/render.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/tables/tables.h"
#include "color/lab.h"
#include "fresnel/ground_truth.h"
#include "util/parallel.h"

namespace fl::analysis {
namespace {

using brdf::Vec3;

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Half the image width in scene units: the unit sphere fills 1/1.1 of the frame.
constexpr double kHalfFrame = 1.1;

color::Rgb lerp(const color::Rgb& a, const color::Rgb& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}
color::Rgb mul(const color::Rgb& a, const color::Rgb& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }

// An orthonormal basis (t, b, n) around unit n (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
void basis(const Vec3& n, Vec3& t, Vec3& b) {
  const double s = std::copysign(1.0, n.z);
  const double a = -1.0 / (s + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
  b = {c, s + n.y * n.y * a, -n.y};
}

Vec3 to_world(const Vec3& l, const Vec3& t, const Vec3& b, const Vec3& n) {
  return {l.x * t.x + l.y * b.x + l.z * n.x, l.x * t.y + l.y * b.y + l.z * n.y, l.x * t.z + l.y * b.z + l.z * n.z};
}

}  // namespace

Environment default_environment() {
  Environment e;
  e.zenith = {0.15, 0.25, 0.55};
  e.horizon = {0.60, 0.60, 0.60};
  e.ground = {0.08, 0.07, 0.06};
  e.key_direction = brdf::normalize(Vec3{-0.15, 0.20, 1.0});
  e.key_half_angle_deg = 18.0;
  e.key_radiance = {1.0, 1.0, 1.0};
  return e;
}

color::Rgb environment_radiance(const Environment& env, const Vec3& dir) {
  if (brdf::dot(dir, env.key_direction) >= std::cos(env.key_half_angle_deg * kDegToRad)) return env.key_radiance;
  if (dir.y >= 0.0) return lerp(env.horizon, env.zenith, std::sqrt(std::min(1.0, dir.y)));
  const double t = std::min(1.0, -dir.y / std::sin(7.0 * kDegToRad));
  return lerp(0.5 * env.horizon, env.ground, t);
}

color::Rgb FresnelTable::at(double cos_theta) const {
  const double u = std::clamp(cos_theta, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const size_t i = std::min(static_cast<size_t>(u), values.size() - 2);
  return lerp(values[i], values[i + 1], u - static_cast<double>(i));
}

FresnelTable tabulate_fresnel(const std::function<color::Rgb(double)>& fresnel, int entries) {
  if (entries < 2) throw std::invalid_argument("tabulate_fresnel: at least two entries");
  FresnelTable t;
  t.values.resize(static_cast<size_t>(entries));
  for (int i = 0; i < entries; ++i)
    t.values[i] = fresnel(i == entries - 1 ? 1.0 : static_cast<double>(i) / (entries - 1));
  return t;
}

FresnelTable truth_fresnel_table(const Context& ctx, const spectral::ComplexIorSpectrum& ior, double eta_outside) {
  return tabulate_fresnel([&](double c) { return ground_truth_rgb(ctx, ior, c, eta_outside); });
}

FresnelTable model_fresnel_table(fresnel::Model model, const std::vector<double>& params) {
  return tabulate_fresnel([&](double c) { return fresnel::model_spec(model).evaluate(c, params.data(), false); });
}

color::Rgb shade_specular(const Environment& env, const FresnelTable& fresnel, const Vec3& n, const Vec3& v,
                          double alpha, int samples) {
  const double nov = std::max(1e-4, brdf::dot(n, v));  // grazing: keep the Smith terms finite
  if (alpha < kMirrorAlpha) {
    const Vec3 r = brdf::reflect(v, n);
    return mul(fresnel.at(nov), environment_radiance(env, r));
  }
  Vec3 t, b;
  basis(n, t, b);
  const Vec3 v_local = brdf::normalize(Vec3{brdf::dot(v, t), brdf::dot(v, b), nov});
  // Key-light cone: uniform in solid angle, pdf 1 / (2π(1 − cos δ)).
  const double cos_delta = std::cos(env.key_half_angle_deg * kDegToRad);
  const double cone_pdf = 1.0 / (2.0 * std::numbers::pi * (1.0 - cos_delta));
  Vec3 kt, kb;
  basis(env.key_direction, kt, kb);
  const auto in_cone = [&](const Vec3& l_world) { return brdf::dot(l_world, env.key_direction) >= cos_delta; };

  color::Rgb sum{};
  const auto n_samples = static_cast<std::uint32_t>(samples);
  for (std::uint32_t i = 0; i < n_samples; ++i) {
    const auto p = brdf::hammersley(i, n_samples);
    // Strategy A: the GGX visible normals; f·cos/pdf_A = F(v·h) · G₂/G₁ (brdf::ggx_vndf_weight).
    {
      const Vec3 h = brdf::sample_ggx_vndf(v_local, alpha, p.u1, p.u2);
      const Vec3 l = brdf::reflect(v_local, h);
      if (l.z > 0.0) {
        const Vec3 lw = to_world(l, t, b, n);
        const double pdf_a = brdf::ggx_vndf_reflection_pdf(v_local.z, h.z, alpha);
        const double pdf_b = in_cone(lw) ? cone_pdf : 0.0;
        const double w = pdf_a / (pdf_a + pdf_b);
        const double weight = w * brdf::ggx_vndf_weight(v_local.z, l.z, alpha);
        const auto f = fresnel.at(brdf::dot(v_local, h));
        sum = sum + weight * mul(f, environment_radiance(env, lw));
      }
    }
    // Strategy B: the key light's cone; f·cos/pdf_B = D V F (n·l) / pdf_B.
    {
      const double cos_l = 1.0 - p.u1 * (1.0 - cos_delta);
      const double sin_l = std::sqrt(std::max(0.0, 1.0 - cos_l * cos_l));
      const double phi = 2.0 * std::numbers::pi * p.u2;
      const Vec3 lw = to_world({sin_l * std::cos(phi), sin_l * std::sin(phi), cos_l}, kt, kb, env.key_direction);
      const Vec3 l{brdf::dot(lw, t), brdf::dot(lw, b), brdf::dot(lw, n)};
      if (l.z > 0.0) {
        const Vec3 h = brdf::normalize(Vec3{v_local.x + l.x, v_local.y + l.y, v_local.z + l.z});
        const double pdf_a = brdf::ggx_vndf_reflection_pdf(v_local.z, h.z, alpha);
        const double w = cone_pdf / (pdf_a + cone_pdf);
        const double lobe = brdf::ggx_lobe_cos(v_local, l, alpha);
        const auto f = fresnel.at(brdf::dot(v_local, h));
        sum = sum + (w * lobe / cone_pdf) * mul(f, env.key_radiance);
      }
    }
  }
  return (1.0 / samples) * sum;
}

SphereImage render_sphere(const Environment& env, const FresnelTable& fresnel, const RenderSettings& s) {
  if (s.size_px < 1) throw std::invalid_argument("render_sphere: size must be positive");
  SphereImage img;
  img.width = img.height = s.size_px;
  const size_t count = static_cast<size_t>(s.size_px) * s.size_px;
  img.rgb.assign(3 * count, 0.0f);
  img.alpha.assign(count, 0.0f);
  const double alpha = s.roughness * s.roughness;
  const double scale = 2.0 * kHalfFrame / s.size_px;  // scene units per pixel
  const Vec3 v{0.0, 0.0, 1.0};
  // Shading at a point of the image plane, nullopt-like (false) off the sphere.
  const auto shade_at = [&](double X, double Y, color::Rgb& out) {
    const double r2 = X * X + Y * Y;
    if (r2 >= 1.0) return false;
    out = shade_specular(env, fresnel, {X, Y, std::sqrt(1.0 - r2)}, v, alpha, s.samples);
    return true;
  };
  const auto render_row = [&](int y) {
    for (int x = 0; x < s.size_px; ++x) {
      const double X = (x + 0.5 - 0.5 * s.size_px) * scale;
      const double Y = (0.5 * s.size_px - y - 0.5) * scale;
      const double r = std::hypot(X, Y);
      color::Rgb c{};
      double cover = 0.0;
      if (r < 1.0 - scale) {  // the whole pixel is on the sphere
        shade_at(X, Y, c);
        cover = 1.0;
      } else if (r < 1.0 + scale) {  // silhouette: 4×4 sub-samples
        constexpr int kSub = 4;
        for (int j = 0; j < kSub; ++j)
          for (int i = 0; i < kSub; ++i) {
            color::Rgb sc;
            if (shade_at(X + ((i + 0.5) / kSub - 0.5) * scale, Y - ((j + 0.5) / kSub - 0.5) * scale, sc)) {
              c = c + sc;
              cover += 1.0;
            }
          }
        c = (1.0 / (kSub * kSub)) * c;  // premultiplied by coverage
        cover /= kSub * kSub;
      }
      const size_t k = static_cast<size_t>(y) * s.size_px + x;
      img.rgb[3 * k] = static_cast<float>(c.r);
      img.rgb[3 * k + 1] = static_cast<float>(c.g);
      img.rgb[3 * k + 2] = static_cast<float>(c.b);
      img.alpha[k] = static_cast<float>(cover);
    }
  };
  parallel_for(static_cast<size_t>(s.size_px), [&](size_t y) { render_row(static_cast<int>(y)); }, s.threads);
  return img;
}

MaterialRender render_material(const Context& ctx, const LoadedMaterial& m, const fresnel::ModelSpec* model,
                               const std::string& kind, const RenderSettings& settings) {
  const auto env = default_environment();
  MaterialRender r;
  r.truth = render_sphere(env, truth_fresnel_table(ctx, m.ior, ctx.settings().eta_outside), settings);
  if (!model) {
    r.shown = r.truth;
    return r;
  }
  const std::vector<LoadedMaterial> one{m};
  r.params = model_params(study_one(ctx, one, kind), model->model, kind);
  r.shown = render_sphere(env, model_fresnel_table(model->model, r.params), settings);
  r.de2000 = de2000_image(ctx, r.truth, r.shown);
  return r;
}

std::vector<double> de2000_image(const Context& ctx, const SphereImage& a, const SphereImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("de2000_image: sizes differ");
  std::vector<double> out(a.alpha.size(), std::nan(""));
  for (size_t k = 0; k < out.size(); ++k) {
    if (!(a.alpha[k] > 0.0f) || !(b.alpha[k] > 0.0f)) continue;
    const color::Rgb ca{a.rgb[3 * k] / a.alpha[k], a.rgb[3 * k + 1] / a.alpha[k], a.rgb[3 * k + 2] / a.alpha[k]};
    const color::Rgb cb{b.rgb[3 * k] / b.alpha[k], b.rgb[3 * k + 1] / b.alpha[k], b.rgb[3 * k + 2] / b.alpha[k]};
    out[k] = color::ciede2000(ctx.rgb_to_lab(ca), ctx.rgb_to_lab(cb));
  }
  return out;
}

}  // namespace fl::analysis
