// `plot strip | curves` and `render`: figures and sphere renders of one material.
#include <memory>
#include <optional>

#include "cli/app.h"
#include "fresnel/registered_models.h"
#include "jobs/pictures.h"

namespace fl::cli {
namespace {

void add_plot_subcommand(CLI::App& plot, GlobalOptions& g, Runner& selected, const char* name,
                         const char* help, const char* default_models, const char* out_help) {
  auto* sub = plot.add_subcommand(name, help);
  auto r = std::make_shared<jobs::PlotRequest>();
  r->figure = name;
  r->models = default_models;
  sub->add_option("MATERIALS", r->materials, kMaterialsHelp)->required();
  sub->add_option("--models", r->models,
                  "comma-separated models, or all: " + fresnel::model_names())
      ->capture_default_str();
  sub->add_option("--params", r->params,
                  "derived (the spectral procedure), fitted (to the curve) or rendered (to the "
                  "render under IBL and area lights)")
      ->capture_default_str();
  sub->add_option("--out", r->out,
                  std::string(out_help) +
                      "; with several materials '{name}' in it is replaced by each one's name")
      ->required()
      ->check(output_location());
  sub->callback([&g, &selected, r] {
    selected = [&g, r] {
      jobs::check_plot_request(*r);
      const auto ctx = make_context(g);
      const auto ms = load_many(g, ctx, r->materials);
      const draw::LabelFont font(g.label_font);
      return write_output(g, jobs::plot_outputs(ctx, ms, *r, font));
    };
  });
}

}  // namespace

void add_plot(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* plot = app.add_subcommand(
      "plot", "figures: strip (colour strips) | curves (reflectance and ΔE2000 plots)");
  plot->require_subcommand(1);
  add_plot_subcommand(
      *plot, g, selected, "strip",
      "stacked colour strips over 0°–90° and 80°–90°: ground truth and each model (sRGB via OCIO)",
      "all", "output file (.png, .svg or .pdf)");
  add_plot_subcommand(
      *plot, g, selected, "curves",
      "R, G, B reflectance against angle (truth and models) and ΔE2000 against angle",
      "schlick,f82,gulbrandsen", "output file (.png, .svg or .pdf)");
}

namespace {

// render's lighting: an EXR environment, its colour space, rotation and exposure.
void add_environment_options(CLI::App& sub, jobs::RenderRequest& r) {
  sub.add_option("--env", r.env,
                 "a latitude-longitude OpenEXR environment (default: the analytic neutral studio)");
  sub.add_option(
      "--env-space", r.env_space,
      "the environment's colour space (default: its chromaticities attribute, else lin_rec709)");
  sub.add_option("--env-rotate", r.env_rotate_deg,
                 "environment rotation about the vertical axis, degrees")
      ->capture_default_str();
  sub.add_option("--env-exposure", r.env_exposure_ev,
                 "stops above the environment's normalization (mean luminance 1: a white diffuse "
                 "ball reads 1)")
      ->capture_default_str();
}

}  // namespace

void add_render(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub =
      app.add_subcommand("render",
                         "a GGX sphere in an analytic neutral studio with a key light or a "
                         "latitude-longitude EXR environment: FILE.exr and "
                         "FILE.png; with a model also FILE.truth.png and the ΔE2000 heat "
                         "map FILE.de2000.png; with --compare the truth "
                         "and every model, heat maps, an animated flip (FILE.flip.webp) and "
                         "a contact sheet (FILE.sheet.png)");
  auto r = std::make_shared<jobs::RenderRequest>();
  sub->add_option("MATERIALS", r->materials, kMaterialsHelp)->required();
  sub->add_option("--model", r->model,
                  "truth (spectral ground truth) or a model: " + fresnel::model_names())
      ->capture_default_str();
  auto* compare =
      sub->add_option("--compare", r->compare,
                      "comma-separated models (or all) rendered against the truth in one pass");
  sub->get_option("--model")->excludes(compare);
  sub->add_option(
         "--params", r->params,
         "derived, fitted (to the curve) or rendered (to the render under IBL and area lights)")
      ->capture_default_str();
  add_environment_options(*sub, *r);
  sub->add_option("--roughness", r->settings.roughness,
                  "GGX perceptual roughness (0: perfect mirror)")
      ->capture_default_str();
  auto* size = sub->add_option("--size", r->settings.size_px,
                               "image width and height in pixels (odd: a pixel at the centre; "
                               "default 255, with --compare 512)");
  sub->add_option("--flip", r->flip,
                  "the --compare flip's format: webp (lossless, FILE.flip.webp) or gif (256 "
                  "colours per frame, dithered, FILE.flip.gif)")
      ->capture_default_str();
  sub->add_option("--samples", r->settings.samples, "samples per strategy per shading point")
      ->capture_default_str();
  sub->add_option("--threads", r->settings.threads, "worker threads (0: all cores)")
      ->capture_default_str();
  sub->add_option("--out", r->out,
                  "output .exr (PNGs are written beside it); with several materials '{name}' in it "
                  "is replaced by each "
                  "one's name")
      ->required()
      ->check(output_location());
  sub->callback([&g, &selected, r, size] {
    if (!r->compare.empty() && size->count() == 0) r->settings.size_px = jobs::kCompareSizePx;
    selected = [&g, r] {
      jobs::check_render_request(*r);
      r->settings.progress = periodic_progress(g, "render: rows ");
      const auto ctx = make_context(g);
      const auto ms = load_many(g, ctx, r->materials);
      std::optional<draw::LabelFont> font;  // only heat maps and sheets have labels
      if (jobs::render_draws_labels(*r)) font.emplace(g.label_font);
      return write_output(g, jobs::render_outputs(ctx, ms, *r, font ? &*font : nullptr));
    };
  });
}

}  // namespace fl::cli
