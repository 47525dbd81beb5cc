#include "analysis/render/render.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/lut/lut_accuracy.h"
#include "color/lab.h"
#include "fresnel/ground_truth.h"
#include "util/errors.h"
#include "util/parallel.h"

namespace fl::analysis {
namespace {

using brdf::Vec3;

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Half the image width in scene units: the unit sphere fills 1/1.1 of the frame.
constexpr double kHalfFrame = 1.1;

// An orthonormal basis (t, b, n) around unit n (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited").
void basis(const Vec3& n, Vec3& t, Vec3& b) {
  const double s = std::copysign(1.0, n.z);
  const double a = -1.0 / (s + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
  b = {c, s + n.y * n.y * a, -n.y};
}

Vec3 to_world(const Vec3& l, const Vec3& t, const Vec3& b, const Vec3& n) {
  return {l.x * t.x + l.y * b.x + l.z * n.x, l.x * t.y + l.y * b.y + l.z * n.y,
          l.x * t.z + l.y * b.z + l.z * n.z};
}

// environment_radiance with the cosine of the key light's half-angle given.
color::Rgb radiance_with_key(const Environment& env, const Vec3& dir, double cos_key) {
  if (brdf::dot(dir, env.key_direction) >= cos_key) return env.key_radiance;
  if (dir.y >= 0.0) return color::lerp(env.horizon, env.zenith, std::sqrt(std::min(1.0, dir.y)));
  const double t = std::min(1.0, -dir.y / std::sin(7.0 * kDegToRad));
  return color::lerp(0.5 * env.horizon, env.ground, t);
}

// The analytic environment as a light-sampling strategy: directions uniform in the key light's
// cone, pdf 1 / (2π(1 − cos δ)).
struct KeyLightStrategy {
  explicit KeyLightStrategy(const Environment& e)
      : env(e),
        cos_delta(std::cos(e.key_half_angle_deg * kDegToRad)),
        cone_pdf(1.0 / (2.0 * std::numbers::pi * (1.0 - cos_delta))) {
    basis(env.key_direction, kt, kb);
  }
  color::Rgb radiance(const Vec3& d) const { return radiance_with_key(env, d, cos_delta); }
  bool can_sample() const { return env.key_half_angle_deg > 0.0; }
  Vec3 sample(double u1, double u2, double& pdf) const {
    const double cos_l = 1.0 - u1 * (1.0 - cos_delta);
    const double sin_l = std::sqrt(std::max(0.0, 1.0 - cos_l * cos_l));
    const double phi = 2.0 * std::numbers::pi * u2;
    pdf = cone_pdf;
    return to_world({sin_l * std::cos(phi), sin_l * std::sin(phi), cos_l}, kt, kb,
                    env.key_direction);
  }
  double pdf(const Vec3& d) const {
    return can_sample() && brdf::dot(d, env.key_direction) >= cos_delta ? cone_pdf : 0.0;
  }
  void lookup(const Vec3& d, color::Rgb& radiance_out, double& pdf_out) const {
    radiance_out = radiance(d);
    pdf_out = pdf(d);
  }

  const Environment& env;
  double cos_delta, cone_pdf;
  Vec3 kt, kb;
};

// Σ over the tables: out[i] += weight · F_i(v·h) · L.
void accumulate(const std::vector<const FresnelTable*>& tables, double weight,
                const color::Rgb& radiance, double voh, color::Rgb* out) {
  for (size_t i = 0; i < tables.size(); ++i)
    out[i] = out[i] + weight * color::mul(tables[i]->at(voh), radiance);
}

// What Hammersley point i of `samples` gives every shading point, drawn once per render: the
// lighting strategy's direction (pdf 0: none) and the point of the unit disk the visible-normal
// sampler warps (brdf::GgxVndfSampler).
struct LightSample {
  Vec3 dir;
  double pdf = 0;
  color::Rgb radiance;
  brdf::DiskPoint disk;
};

template <class S>
std::vector<LightSample> light_samples(const S& light, int samples) {
  std::vector<LightSample> out(static_cast<size_t>(samples));
  const auto n = static_cast<std::uint32_t>(samples);
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto p = brdf::hammersley(i, n);
    auto& ls = out[i];
    ls.disk = brdf::disk_point(p.u1, p.u2);
    if (!light.can_sample()) continue;
    ls.dir = light.sample(p.u1, p.u2, ls.pdf);
    if (ls.pdf > 0.0) ls.radiance = light.radiance(ls.dir);
  }
  return out;
}

// shade_specular for one lighting strategy S (radiance, lookup, can_sample, sample, pdf).
template <class S>
void shade_with(const S& light, const std::vector<LightSample>& drawn,
                const std::vector<const FresnelTable*>& tables, const Vec3& n, const Vec3& v,
                double alpha, color::Rgb* out) {
  std::fill(out, out + tables.size(), color::Rgb{});
  const double nov = std::max(1e-4, brdf::dot(n, v));  // grazing: keep the Smith terms finite
  if (alpha < kMirrorAlpha) {
    accumulate(tables, 1.0, light.radiance(brdf::reflect(v, n)), nov, out);
    return;
  }
  Vec3 t, b;
  basis(n, t, b);
  const Vec3 v_local = brdf::normalize(Vec3{brdf::dot(v, t), brdf::dot(v, b), nov});
  const brdf::GgxVndfSampler vndf(v_local, alpha);
  const brdf::GgxVndfWeight view(v_local.z, alpha);
  const auto n_samples = static_cast<std::uint32_t>(drawn.size());
  for (std::uint32_t i = 0; i < n_samples; ++i) {
    // Strategy A: the GGX visible normals; f·cos/pdf_A = F(v·h) · G₂/G₁ (brdf::ggx_vndf_weight).
    const Vec3 h = vndf(drawn[i].disk);
    const Vec3 l = brdf::reflect(v_local, h);
    if (l.z > 0.0) {
      const Vec3 lw = to_world(l, t, b, n);
      const double pdf_a = view.reflection_pdf(h.z);
      color::Rgb radiance;
      double pdf_b = 0;
      light.lookup(lw, radiance, pdf_b);
      const double w = pdf_a / (pdf_a + pdf_b);
      accumulate(tables, w * view(l.z), radiance, brdf::dot(v_local, h), out);
    }
    // Strategy B: the lighting's own directions; f·cos/pdf_B = D V F (n·l) / pdf_B.
    const LightSample& ls = drawn[i];
    if (!(ls.pdf > 0.0)) continue;
    const Vec3 lb{brdf::dot(ls.dir, t), brdf::dot(ls.dir, b), brdf::dot(ls.dir, n)};
    if (lb.z <= 0.0) continue;
    const Vec3 hb = brdf::normalize(Vec3{v_local.x + lb.x, v_local.y + lb.y, v_local.z + lb.z});
    const double pdf_a = view.reflection_pdf(hb.z);
    const double w = ls.pdf / (pdf_a + ls.pdf);
    accumulate(tables, w * view.lobe_cos(lb.z, hb.z) / ls.pdf, ls.radiance, brdf::dot(v_local, hb),
               out);
  }
  for (size_t k = 0; k < tables.size(); ++k)
    out[k] = (1.0 / static_cast<double>(n_samples)) * out[k];
}

// Calls f with the lighting's sampling strategy.
template <class F>
auto with_strategy(const SceneLight& light, const F& f) {
  if (const auto* env = std::get_if<Environment>(&light)) return f(KeyLightStrategy(*env));
  return f(std::get<EnvironmentMap>(light));
}

// One pixel of every image: its colour (premultiplied by coverage) per table, and its coverage.
template <class S>
double render_pixel(const S& light, const std::vector<LightSample>& drawn,
                    const std::vector<const FresnelTable*>& tables, const RenderSettings& s,
                    double X, double Y, double scale, std::vector<color::Rgb>& c,
                    std::vector<color::Rgb>& sub) {
  const double alpha = s.roughness * s.roughness;
  const Vec3 v{0.0, 0.0, 1.0};
  const auto shade_at = [&](double px, double py, color::Rgb* out) {
    const double r2 = px * px + py * py;
    if (r2 >= 1.0) return false;
    shade_with(light, drawn, tables, {px, py, std::sqrt(1.0 - r2)}, v, alpha, out);
    return true;
  };
  std::fill(c.begin(), c.end(), color::Rgb{});
  const double r = std::hypot(X, Y);
  if (r < 1.0 - scale) {  // the whole pixel is on the sphere
    shade_at(X, Y, c.data());
    return 1.0;
  }
  if (r >= 1.0 + scale) return 0.0;
  constexpr int kSub = 4;  // silhouette: 4×4 sub-samples
  double cover = 0.0;
  for (int j = 0; j < kSub; ++j)
    for (int i = 0; i < kSub; ++i) {
      if (!shade_at(X + ((i + 0.5) / kSub - 0.5) * scale, Y - ((j + 0.5) / kSub - 0.5) * scale,
                    sub.data()))
        continue;
      for (size_t k = 0; k < c.size(); ++k) c[k] = c[k] + sub[k];
      cover += 1.0;
    }
  for (auto& v_k : c) v_k = (1.0 / (kSub * kSub)) * v_k;  // premultiplied by coverage
  return cover / (kSub * kSub);
}

// The image-plane point of pixel (x, y)'s centre, in scene units.
void pixel_centre(int x, int y, int width, int height, double& X, double& Y) {
  const double scale = 2.0 * kHalfFrame / width;
  X = (x + 0.5 - 0.5 * width) * scale;
  Y = (0.5 * height - y - 0.5) * scale;
}

template <class S>
std::vector<SphereImage> render_with(const S& light, const std::vector<const FresnelTable*>& tables,
                                     const RenderSettings& s) {
  const size_t count = static_cast<size_t>(s.size_px) * s.size_px;
  std::vector<SphereImage> images(tables.size());
  for (auto& img : images) {
    img.width = img.height = s.size_px;
    img.rgb.assign(3 * count, 0.0f);
    img.alpha.assign(count, 0.0f);
  }
  const double scale = 2.0 * kHalfFrame / s.size_px;  // scene units per pixel
  const auto drawn = light_samples(light, s.samples);
  ProgressCounter rows_done(s.progress, s.size_px);
  parallel_for(
      static_cast<size_t>(s.size_px),
      [&](size_t row) {
        std::vector<color::Rgb> c(tables.size()), sub(tables.size());
        const int y = static_cast<int>(row);
        for (int x = 0; x < s.size_px; ++x) {
          double X = 0, Y = 0;
          pixel_centre(x, y, s.size_px, s.size_px, X, Y);
          const double cover = render_pixel(light, drawn, tables, s, X, Y, scale, c, sub);
          const size_t k = static_cast<size_t>(y) * s.size_px + x;
          for (size_t i = 0; i < tables.size(); ++i) {
            images[i].rgb[3 * k] = static_cast<float>(c[i].r);
            images[i].rgb[3 * k + 1] = static_cast<float>(c[i].g);
            images[i].rgb[3 * k + 2] = static_cast<float>(c[i].b);
            images[i].alpha[k] = static_cast<float>(cover);
          }
        }
        rows_done.add(1);
      },
      s.threads);
  return images;
}

}  // namespace

Environment default_environment() {
  Environment e;
  e.zenith = {0.80, 0.80, 0.80};
  e.horizon = {0.40, 0.40, 0.40};
  e.ground = {0.05, 0.05, 0.05};
  e.key_direction = brdf::normalize(Vec3{-0.15, 0.20, 1.0});
  e.key_half_angle_deg = 18.0;
  e.key_radiance = {1.0, 1.0, 1.0};
  return e;
}

color::Rgb environment_radiance(const Environment& env, const Vec3& dir) {
  return radiance_with_key(env, dir, std::cos(env.key_half_angle_deg * kDegToRad));
}

color::Rgb FresnelTable::at(double cos_theta) const {
  const double u = std::clamp(cos_theta, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const size_t i = std::min(static_cast<size_t>(u), values.size() - 2);
  return color::lerp(values[i], values[i + 1], u - static_cast<double>(i));
}

FresnelTable tabulate_fresnel(const std::function<color::Rgb(double)>& fresnel, int entries) {
  if (entries < 2) throw std::invalid_argument("tabulate_fresnel: at least two entries");
  FresnelTable t;
  t.values.resize(static_cast<size_t>(entries));
  for (int i = 0; i < entries; ++i)
    t.values[i] = fresnel(i == entries - 1 ? 1.0 : static_cast<double>(i) / (entries - 1));
  return t;
}

FresnelTable truth_fresnel_table(const Context& ctx, const spectral::ComplexIorSpectrum& ior,
                                 double eta_outside) {
  return tabulate_fresnel([&](double c) { return ground_truth_rgb(ctx, ior, c, eta_outside); });
}

FresnelTable model_fresnel_table(fresnel::Model model, const std::vector<double>& params) {
  return tabulate_fresnel(
      [&](double c) { return fresnel::model_spec(model).evaluate(c, params.data(), false); });
}

void shade_specular(const SceneLight& light, const std::vector<const FresnelTable*>& fresnel,
                    const Vec3& n, const Vec3& v, double alpha, int samples, color::Rgb* out) {
  with_strategy(light, [&](const auto& s) {
    shade_with(s, light_samples(s, samples), fresnel, n, v, alpha, out);
    return 0;
  });
}

color::Rgb shade_specular(const SceneLight& light, const FresnelTable& fresnel, const Vec3& n,
                          const Vec3& v, double alpha, int samples) {
  color::Rgb out;
  shade_specular(light, {&fresnel}, n, v, alpha, samples, &out);
  return out;
}

std::vector<SphereImage> render_spheres(const SceneLight& light,
                                        const std::vector<const FresnelTable*>& fresnel,
                                        const RenderSettings& s) {
  if (s.size_px < 1) throw std::invalid_argument("render_sphere: size must be positive");
  return with_strategy(light,
                       [&](const auto& strategy) { return render_with(strategy, fresnel, s); });
}

SphereImage render_sphere(const SceneLight& light, const FresnelTable& fresnel,
                          const RenderSettings& s) {
  return std::move(render_spheres(light, {&fresnel}, s).front());
}

HeatmapStats heatmap_stats(const std::vector<double>& de, int width, int height) {
  HeatmapStats st;
  const size_t bands = st.band_upper_deg.size();
  std::vector<double> sum(bands, 0.0);
  std::vector<long long> count(bands, 0);
  double total = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double e = de[static_cast<size_t>(y) * width + x];
      if (!std::isfinite(e)) continue;
      double X = 0, Y = 0;
      pixel_centre(x, y, width, height, X, Y);
      const double theta_deg = std::acos(std::sqrt(std::max(0.0, 1.0 - X * X - Y * Y))) / kDegToRad;
      size_t b = 0;
      while (b + 1 < bands && theta_deg >= st.band_upper_deg[b]) ++b;
      sum[b] += e, ++count[b], total += e, ++st.pixels;
      st.max = std::max(st.max, e);
    }
  st.mean = st.pixels ? total / static_cast<double>(st.pixels) : 0.0;
  for (size_t b = 0; b < bands; ++b)
    st.band_mean.push_back(count[b] ? sum[b] / static_cast<double>(count[b]) : std::nan(""));
  return st;
}

std::vector<SphereImage> render_truth_and_models(const Context& ctx, const LoadedMaterial& m,
                                                 const SceneLight& light,
                                                 const std::vector<fresnel::Model>& models,
                                                 const std::vector<std::vector<double>>& params,
                                                 const RenderSettings& settings) {
  if (params.size() != models.size())
    throw std::invalid_argument("render_truth_and_models: one parameter set per model");
  std::vector<FresnelTable> tables{truth_fresnel_table(ctx, m.ior, ctx.settings().eta_outside)};
  for (size_t i = 0; i < models.size(); ++i)
    tables.push_back(model_fresnel_table(models[i], params[i]));
  std::vector<const FresnelTable*> all;
  for (const auto& t : tables) all.push_back(&t);
  return render_spheres(light, all, settings);
}

MaterialRender render_material(const Context& ctx, const LoadedMaterial& m, const SceneLight& light,
                               const std::vector<fresnel::Model>& models, const std::string& kind,
                               const RenderSettings& settings) {
  std::vector<std::vector<double>> params;
  if (!models.empty()) {
    const std::vector<LoadedMaterial> one{m};
    const auto st = study_one(ctx, one, kind, models);
    for (const auto model : models) params.push_back(model_params(st, model, kind));
  }
  auto images = render_truth_and_models(ctx, m, light, models, params, settings);
  MaterialRender r;
  r.truth = std::move(images[0]);
  for (size_t i = 0; i < models.size(); ++i) {
    ModelRender mr{models[i], params[i], std::move(images[i + 1]), {}, {}};
    mr.de2000 = de2000_image(ctx, r.truth, mr.image);
    mr.stats = heatmap_stats(mr.de2000, mr.image.width, mr.image.height);
    r.models.push_back(std::move(mr));
  }
  return r;
}

std::vector<double> de2000_image(const Context& ctx, const SphereImage& a, const SphereImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("de2000_image: sizes differ");
  std::vector<double> out(a.alpha.size(), std::nan(""));
  for (size_t k = 0; k < out.size(); ++k) {
    if (!(a.alpha[k] > 0.0f) || !(b.alpha[k] > 0.0f)) continue;
    const color::Rgb ca{a.rgb[3 * k] / a.alpha[k], a.rgb[3 * k + 1] / a.alpha[k],
                        a.rgb[3 * k + 2] / a.alpha[k]};
    const color::Rgb cb{b.rgb[3 * k] / b.alpha[k], b.rgb[3 * k + 1] / b.alpha[k],
                        b.rgb[3 * k + 2] / b.alpha[k]};
    out[k] = color::ciede2000(ctx.rgb_to_lab(ca), ctx.rgb_to_lab(cb));
  }
  return out;
}

}  // namespace fl::analysis
