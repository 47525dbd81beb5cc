// `render`: the sphere render of a material as EXR and PNG files, and flip comparisons
// (jobs/pictures.h).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>

#include "analysis/render/environment_file.h"
#include "analysis/render/figure_data.h"
#include "draw/drawing.h"
#include "draw/figures.h"
#include "draw/flip.h"
#include "draw/png.h"
#include "io/exr.h"
#include "io/gif.h"
#include "io/webp.h"
#include "jobs/pictures.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::jobs {
namespace {

// A flip frame stays on screen this long (milliseconds; the GIF counts hundredths of a second).
constexpr int kFlipDelayMs = 900;

// The render through the context's view on the backdrop of m's class (dielectrics: reflection
// only, over grey).
io::Image8 display_image(const analysis::Context& ctx, const analysis::SphereImage& img,
                         const analysis::LoadedMaterial& m) {
  return io::Image8(img.width, img.height,
                    analysis::sphere_display(ctx.display(), img,
                                             analysis::backdrop_for(m.material.material_class)));
}

bool reflection_only(const analysis::LoadedMaterial& m) {
  return analysis::reflection_only(m.material.material_class);
}

const fresnel::ModelSpec* render_model(const RenderRequest& r) {
  return r.model == "truth" ? nullptr : &fresnel::model_from_name(r.model);
}

std::vector<fresnel::Model> render_models(const RenderRequest& r) {
  if (!r.compare.empty()) return parse_models(r.compare);
  if (const auto* spec = render_model(r)) return {spec->model};
  return {};
}

std::string parameter_text(fresnel::Model model, const std::vector<double>& params) {
  std::string s;
  const auto names = fresnel::model_spec(model).param_names();
  for (size_t i = 0; i < names.size(); ++i)
    s += fmt::format("{}{}={:.6f}", i ? " " : "", names[i], params[i]);
  return s;
}

// The lighting and the sentence describing it (messages and EXR attributes).
struct Scene {
  analysis::SceneLight light;
  std::string lighting;
  std::vector<std::string> warnings;
};

Scene render_scene(const analysis::Context& ctx, const RenderRequest& r) {
  if (r.env.empty())
    return {analysis::default_environment(),
            "analytic neutral studio + 18 deg key-light disc containing the view axis "
            "(default_environment)",
            {}};
  auto env = load_environment(ctx, r.env, r.env_space, r.env_rotate_deg, r.env_exposure_ev);
  Scene s{std::move(env.map),
          fmt::format("environment {}: {}", std::filesystem::path(r.env).filename().string(),
                      env.description()),
          {}};
  if (env.clamped_negative > 0)
    s.warnings.push_back(
        fmt::format("render: {}: {} negative values read as 0", r.env, env.clamped_negative));
  return s;
}

// The EXR header shared by every render: material, colour space (with its chromaticities), scene.
io::ExrImage exr_header(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                        const RenderRequest& r, const Scene& scene, int size) {
  io::ExrImage exr;
  exr.width = exr.height = size;
  const auto c = color::chromaticities_of(ctx.space());
  exr.chromaticities =
      std::array<float, 8>{float(c.red.x),  float(c.red.y),  float(c.green.x), float(c.green.y),
                           float(c.blue.x), float(c.blue.y), float(c.white.x), float(c.white.y)};
  exr.string_attributes = {
      {"fresnelLab:material", m.material.name},
      {"fresnelLab:colorSpace",
       fmt::format("{} (linear), illuminant {}", ctx.settings().space, ctx.settings().illuminant)},
      {"fresnelLab:scene",
       "unit sphere, orthographic camera along -z, GGX specular only "
       "(src/analysis/render/render.h); " +
           scene.lighting}};
  exr.float_attributes = {{"fresnelLab:roughness", static_cast<float>(r.settings.roughness)},
                          {"fresnelLab:samples", static_cast<float>(r.settings.samples)}};
  return exr;
}

// Channels `names` of `exr` filled from premultiplied RGB (+ alpha) or a scalar image.
void add_channels(io::ExrImage& exr, const std::vector<std::string>& names,
                  const std::vector<const std::vector<float>*>& planes,
                  const std::vector<int>& strides, const std::vector<int>& offsets) {
  const size_t old_nc = exr.channels.size(), nc = old_nc + names.size(),
               count = static_cast<size_t>(exr.width) * exr.height;
  std::vector<float> pixels(count * nc);
  for (size_t k = 0; k < count; ++k) {
    for (size_t c = 0; c < old_nc; ++c) pixels[k * nc + c] = exr.pixels[k * old_nc + c];
    for (size_t c = 0; c < names.size(); ++c)
      pixels[k * nc + old_nc + c] = (*planes[c])[k * strides[c] + offsets[c]];
  }
  exr.channels.insert(exr.channels.end(), names.begin(), names.end());
  exr.pixels = std::move(pixels);
}

void add_rgba(io::ExrImage& exr, const std::string& prefix, const analysis::SphereImage& img,
              bool alpha) {
  std::vector<std::string> names{prefix + "R", prefix + "G", prefix + "B"};
  std::vector<const std::vector<float>*> planes{&img.rgb, &img.rgb, &img.rgb};
  std::vector<int> strides{3, 3, 3}, offsets{0, 1, 2};
  if (alpha)
    names.push_back(prefix + "A"), planes.push_back(&img.alpha), strides.push_back(1),
        offsets.push_back(0);
  add_channels(exr, names, planes, strides, offsets);
}

std::string model_label(fresnel::Model model, const std::string& kind) {
  return fmt::format("{} ({} parameters)", fresnel::model_spec(model).name, kind);
}

io::Files single_files(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                       const RenderRequest& r, const Scene& scene,
                       const analysis::MaterialRender& images, const draw::LabelFont* font) {
  const std::string base = r.out.substr(0, r.out.size() - 4);
  const auto& shown = images.models.empty() ? images.truth : images.models[0].image;
  io::ExrImage exr = exr_header(ctx, m, r, scene, shown.width);
  add_rgba(exr, "", shown, true);
  const bool model = !images.models.empty();
  exr.string_attributes.emplace_back(
      "fresnelLab:fresnel",
      model ? model_label(images.models[0].model, r.params) : "spectral ground truth");
  exr.string_attributes.emplace_back(
      "fresnelLab:parameters",
      model ? parameter_text(images.models[0].model, images.models[0].params) : "");
  io::Files files;
  files.emplace_back(r.out, io::encode_exr(exr));
  files.emplace_back(base + ".png", draw::encode_png(display_image(ctx, shown, m)));
  if (model) {
    files.emplace_back(base + ".truth.png", draw::encode_png(display_image(ctx, images.truth, m)));
    const auto title = fmt::format("{}: ΔE2000, truth vs {}", m.material.name,
                                   fresnel::model_spec(images.models[0].model).name);
    files.emplace_back(base + ".de2000.png",
                       draw::encode(draw::heatmap_drawing(images.models[0].de2000, shown.width,
                                                          shown.height, title, *font),
                                    draw::FileType::Png, *font));
  }
  return files;
}

// The layered EXR of a comparison: the truth as R, G, B, A, each model as MODEL.R, .G, .B, .de2000.
std::string compare_exr(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                        const RenderRequest& r, const Scene& scene,
                        const analysis::MaterialRender& images) {
  io::ExrImage exr = exr_header(ctx, m, r, scene, images.truth.width);
  add_rgba(exr, "", images.truth, true);
  std::string fresnel = "R, G, B: spectral ground truth";
  std::vector<std::vector<float>> de(images.models.size());
  for (size_t i = 0; i < images.models.size(); ++i) {
    const auto& mr = images.models[i];
    const std::string name = fresnel::model_spec(mr.model).name;
    add_rgba(exr, name + ".", mr.image, false);
    de[i].assign(mr.de2000.begin(), mr.de2000.end());
    add_channels(exr, {name + ".de2000"}, {&de[i]}, {1}, {0});
    fresnel += fmt::format("; {}.*: {} [{}]", name, model_label(mr.model, r.params),
                           parameter_text(mr.model, mr.params));
  }
  exr.string_attributes.emplace_back("fresnelLab:fresnel", fresnel);
  return io::encode_exr(exr);
}

draw::ContactSheet contact_sheet(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                                 const RenderRequest& r, const Scene& scene,
                                 const analysis::MaterialRender& images) {
  draw::ContactSheet sheet;
  sheet.title = fmt::format("{}: ground truth against each model (roughness {:g})", m.material.name,
                            r.settings.roughness);
  sheet.notes = {scene.lighting,
                 fmt::format("{} working space, {} illuminant; GGX specular, {} samples per "
                             "strategy; ΔE2000 per pixel "
                             "against the truth (CIELAB relative to Y = 1)",
                             ctx.settings().space, ctx.settings().illuminant, r.settings.samples),
                 "pictures through OpenColorIO " + ctx.display().description() +
                     "; ΔE2000 on the scene-linear values"};
  if (reflection_only(m)) {
    sheet.title += ", reflection only";
    sheet.notes.push_back(std::string(analysis::kReflectionOnlyNote) +
                          ": the render holds the surface reflection, not the light through it");
  }
  sheet.truth = display_image(ctx, images.truth, m);
  for (const auto& mr : images.models)
    sheet.rows.push_back({model_label(mr.model, r.params), display_image(ctx, mr.image, m),
                          mr.de2000, mr.stats.mean, mr.stats.max});
  return sheet;
}

// The flip's frames: per model the truth, the model and its difference frame.
// The truth frame's second line names the view, or for a dielectric that it shows the reflection
// only.
std::vector<io::Image8> flip_frames(const draw::ContactSheet& sheet,
                                    const analysis::MaterialRender& images, double scale,
                                    const color::DisplayTransform& view,
                                    analysis::Backdrop backdrop, const draw::LabelFont& font) {
  const bool reflection = backdrop == analysis::Backdrop::ReflectionOnMidGrey;
  const auto values = [&](const analysis::SphereImage& img) {
    return draw::DisplayValues{img.width, img.height,
                               analysis::sphere_display_values(view, img, backdrop)};
  };
  const draw::DisplayValues truth_values = values(images.truth);
  std::vector<io::Image8> frames;
  const io::Image8 truth =
      draw::flip_frame(sheet.truth, "ground truth (spectral)",
                       reflection ? analysis::kReflectionOnlyNote : view.display_and_view(), font);
  for (size_t i = 0; i < images.models.size(); ++i) {
    const auto& row = sheet.rows[i];
    const std::string name = fresnel::model_spec(images.models[i].model).name;
    frames.push_back(truth);
    frames.push_back(draw::flip_frame(
        row.render, row.label,
        fmt::format("ΔE2000 mean {:.2f}, max {:.2f}", row.mean_de2000, row.max_de2000), font));
    frames.push_back(draw::flip_difference_frame(truth_values, values(images.models[i].image),
                                                 row.de2000, scale, name,
                                                 row.label + ": difference", font));
  }
  return frames;
}

io::Files compare_files(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                        const RenderRequest& r, const Scene& scene,
                        const analysis::MaterialRender& images, const draw::LabelFont& font) {
  const std::string base = r.out.substr(0, r.out.size() - 4);
  const draw::ContactSheet sheet = contact_sheet(ctx, m, r, scene, images);
  io::Files files;
  files.emplace_back(r.out, compare_exr(ctx, m, r, scene, images));
  files.emplace_back(base + ".truth.png", draw::encode_png(sheet.truth));
  const double scale = draw::contact_sheet_scale(sheet);
  for (size_t i = 0; i < images.models.size(); ++i) {
    const auto& mr = images.models[i];
    const std::string name = fresnel::model_spec(mr.model).name;
    files.emplace_back(base + "." + name + ".png", draw::encode_png(sheet.rows[i].render));
    const auto title = fmt::format("{}: ΔE2000, truth vs {}", m.material.name, name);
    files.emplace_back(base + "." + name + ".de2000.png",
                       draw::encode(draw::heatmap_drawing(mr.de2000, mr.image.width,
                                                          mr.image.height, title, font, scale),
                                    draw::FileType::Png, font));
  }
  const auto frames = flip_frames(sheet, images, scale, ctx.display(),
                                  analysis::backdrop_for(m.material.material_class), font);
  if (r.flip == "gif")
    files.emplace_back(base + ".flip.gif", io::encode_gif(frames, kFlipDelayMs / 10));
  else
    files.emplace_back(base + ".flip.webp", io::encode_webp(frames, kFlipDelayMs));
  files.emplace_back(base + ".sheet.png", draw::encode(draw::contact_sheet_drawing(sheet, font),
                                                       draw::FileType::Png, font));
  return files;
}

std::string de2000_message(const analysis::ModelRender& mr) {
  const auto& st = mr.stats;
  std::string bands;
  double lo = 0;
  for (size_t b = 0; b < st.band_mean.size(); ++b) {
    bands += fmt::format("{}{:g}–{:g}° {:.3f}", b ? ", " : "", lo, st.band_upper_deg[b],
                         st.band_mean[b]);
    lo = st.band_upper_deg[b];
  }
  return fmt::format(
      "render: ΔE2000 truth vs {}: mean {:.3f}, max {:.3f} over {} pixels; mean by view angle: {}",
      fresnel::model_spec(mr.model).name, st.mean, st.max, st.pixels, bands);
}

}  // namespace

void check_render_request(const RenderRequest& r) {
  if (io::lower_extension(r.out) != ".exr")
    throw InputError(r.out, 0,
                     "the render output must be an .exr file (the PNGs are written beside it)");
  analysis::parameter_set_from_name(r.params);
  const auto& rs = r.settings;
  if (!(rs.roughness >= 0.0 && rs.roughness <= 1.0))
    throw InputError(fmt::format("--roughness {} out of range (0 to 1)", rs.roughness));
  if (rs.size_px < 3 || rs.size_px > 4097)
    throw InputError(fmt::format("--size {} out of range (3 to 4097)", rs.size_px));
  if (rs.samples < 1 || rs.samples > 65536)
    throw InputError(fmt::format("--samples {} out of range (1 to 65536)", rs.samples));
  if (rs.threads < 0)
    throw InputError(fmt::format("--threads {} must be 0 (all) or positive", rs.threads));
  if (!std::isfinite(r.env_rotate_deg))
    throw InputError("--env-rotate must be a finite angle in degrees");
  if (!(std::abs(r.env_exposure_ev) <= 32))
    throw InputError("--env-exposure must be between -32 and 32 stops");
  render_model(r);
  if (!r.compare.empty()) parse_models(r.compare);
  if (r.flip != "webp" && r.flip != "gif")
    throw InputError("--flip: " +
                     unknown_name_message("flip format", r.flip, {{"webp", {}}, {"gif", {}}}));
}

bool render_draws_labels(const RenderRequest& r) {
  return !render_models(r).empty();
}

io::Output render_output(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                         const RenderRequest& r, const draw::LabelFont* font) {
  check_render_request(r);
  if (!font && render_draws_labels(r))
    throw std::invalid_argument("render_output: heat maps need a label font");
  const auto& rs = r.settings;
  const Scene scene = render_scene(ctx, r);
  const auto t0 = std::chrono::steady_clock::now();
  const auto images =
      analysis::render_material(ctx, m, scene.light, render_models(r), r.params, rs);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  io::Output o;
  o.messages = scene.warnings;
  o.messages.push_back(
      fmt::format("render: {} × {} px, roughness {:g}, {} samples per strategy, {} image(s) in one "
                  "pass ({:.2f} s); {}",
                  rs.size_px, rs.size_px, rs.roughness, rs.samples, 1 + images.models.size(), secs,
                  scene.lighting));
  o.messages.push_back(
      "render: pictures through OpenColorIO " + ctx.display().description() +
      (reflection_only(m) ? std::string("; ") + analysis::kReflectionOnlyNote : ""));
  o.files = r.compare.empty() ? single_files(ctx, m, r, scene, images, font)
                              : compare_files(ctx, m, r, scene, images, *font);
  const auto& rgb =
      (images.models.empty() || !r.compare.empty() ? images.truth : images.models[0].image).rgb;
  const size_t c = static_cast<size_t>(rs.size_px / 2) * rs.size_px + rs.size_px / 2;
  o.messages.push_back(fmt::format("render: centre pixel ({:.5f}, {:.5f}, {:.5f})", rgb[3 * c],
                                   rgb[3 * c + 1], rgb[3 * c + 2]));
  for (const auto& mr : images.models) o.messages.push_back(de2000_message(mr));
  o.messages.push_back("render: wrote " + io::file_list(o.files));
  return o;
}

}  // namespace fl::jobs
