// `render`: the sphere render of a material as EXR and PNG files (report/pictures.h).
#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "analysis/tables/tables.h"
#include "report/exr.h"
#include "analysis/render/figure_data.h"
#include "report/draw.h"
#include "report/figures.h"
#include "report/pictures.h"
#include "report/png.h"
#include "spectral/errors.h"

namespace fl::report {
namespace {

std::string display_png(const analysis::Context& ctx, const analysis::SphereImage& img) {
  return encode_png(Image8(img.width, img.height, analysis::sphere_display(ctx, img)));
}

const fresnel::ModelSpec* render_model(const RenderRequest& r) {
  return r.model == "truth" ? nullptr : &fresnel::model_from_name(r.model);
}

std::string parameter_text(const fresnel::ModelSpec* spec, const std::vector<double>& params) {
  std::string s;
  if (!spec) return s;
  const auto names = spec->param_names();
  for (size_t i = 0; i < names.size(); ++i) s += fmt::format("{}{}={:.6f}", i ? " " : "", names[i], params[i]);
  return s;
}

// Linear, premultiplied RGBA with the scene, material and Fresnel in the header.
ExrImage render_exr(const analysis::Context& ctx, const analysis::LoadedMaterial& m, const RenderRequest& r,
                    const analysis::MaterialRender& images) {
  const auto* spec = render_model(r);
  const auto& shown = images.shown;
  ExrImage exr;
  exr.width = shown.width;
  exr.height = shown.height;
  exr.channels = {"R", "G", "B", "A"};
  exr.pixels.resize(static_cast<size_t>(exr.width) * exr.height * 4);
  for (size_t k = 0; k < shown.alpha.size(); ++k) {
    for (int c = 0; c < 3; ++c) exr.pixels[4 * k + c] = shown.rgb[3 * k + c];
    exr.pixels[4 * k + 3] = shown.alpha[k];
  }
  const std::string label =
      spec ? fmt::format("{} ({} parameters)", spec->name, r.params) : std::string("spectral ground truth");
  exr.string_attributes = {
      {"fresnelLab:material", m.material.name},
      {"fresnelLab:fresnel", label},
      {"fresnelLab:parameters", parameter_text(spec, images.params)},
      {"fresnelLab:colorSpace", fmt::format("{} (linear), illuminant {}", ctx.settings().space, ctx.settings().illuminant)},
      {"fresnelLab:scene",
       "unit sphere, orthographic camera along -z, GGX specular only (analysis/render.h); environment: "
       "analytic sky + 18 deg key-light disc containing the view axis (default_environment)"}};
  exr.float_attributes = {{"fresnelLab:roughness", static_cast<float>(r.settings.roughness)},
                          {"fresnelLab:samples", static_cast<float>(r.settings.samples)}};
  return exr;
}

Files render_files(const analysis::Context& ctx, const analysis::LoadedMaterial& m, const RenderRequest& r,
                   const analysis::MaterialRender& images) {
  const std::string base = r.out.substr(0, r.out.size() - 4);
  Files files;
  files.emplace_back(r.out, encode_exr(render_exr(ctx, m, r, images)));
  files.emplace_back(base + ".png", display_png(ctx, images.shown));
  if (const auto* spec = render_model(r)) {
    files.emplace_back(base + ".truth.png", display_png(ctx, images.truth));
    const auto title = fmt::format("{}: ΔE2000, truth vs {}", m.material.name, spec->name);
    files.emplace_back(base + ".de2000.png",
                       encode(heatmap_drawing(images.de2000, images.shown.width, images.shown.height, title),
                              FileType::Png));
  }
  return files;
}

std::string de2000_message(const std::string& model, const std::vector<double>& de) {
  double sum = 0, max = 0;
  int n = 0;
  for (double v : de)
    if (std::isfinite(v)) sum += v, max = std::max(max, v), ++n;
  return fmt::format("render: ΔE2000 truth vs {}: mean {:.3f}, max {:.3f} over {} pixels", model, n ? sum / n : 0.0,
                     max, n);
}

}  // namespace

void check_render_request(const RenderRequest& r) {
  if (lower_extension(r.out) != ".exr")
    throw InputError(r.out, 0, "the render output must be an .exr file (the PNGs are written beside it)");
  analysis::wants_fitted(r.params);
  const auto& rs = r.settings;
  if (!(rs.roughness >= 0.0 && rs.roughness <= 1.0))
    throw InputError(fmt::format("--roughness {} out of range (0 to 1)", rs.roughness));
  if (rs.size_px < 3 || rs.size_px > 4097) throw InputError(fmt::format("--size {} out of range (3 to 4097)", rs.size_px));
  if (rs.samples < 1 || rs.samples > 65536) throw InputError(fmt::format("--samples {} out of range (1 to 65536)", rs.samples));
  if (rs.threads < 0) throw InputError(fmt::format("--threads {} must be 0 (all) or positive", rs.threads));
  render_model(r);
}

Output render_output(const analysis::Context& ctx, const analysis::LoadedMaterial& m, const RenderRequest& r) {
  check_render_request(r);
  const auto* spec = render_model(r);
  const auto& rs = r.settings;
  const auto t0 = std::chrono::steady_clock::now();
  const auto images = analysis::render_material(ctx, m, spec, r.params, rs);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Output o;
  o.messages.push_back(fmt::format("render: {} × {} px, roughness {:g}, {} samples per strategy ({:.2f} s)",
                                   rs.size_px, rs.size_px, rs.roughness, rs.samples, secs));
  o.files = render_files(ctx, m, r, images);
  const auto& rgb = images.shown.rgb;
  const size_t c = static_cast<size_t>(rs.size_px / 2) * rs.size_px + rs.size_px / 2;
  o.messages.push_back(
      fmt::format("render: centre pixel ({:.5f}, {:.5f}, {:.5f})", rgb[3 * c], rgb[3 * c + 1], rgb[3 * c + 2]));
  if (spec) o.messages.push_back(de2000_message(spec->name, images.de2000));
  o.messages.push_back("render: wrote " + file_list(o.files));
  return o;
}

}  // namespace fl::report
