#pragma once
// The picture commands' outputs: `plot strip | curves` (one figure), `render` (a sphere as EXR and
// PNGs) and the figures `reproduce` writes.
#include <string>
#include <vector>

#include "analysis/render/render.h"
#include "analysis/study/study.h"
#include "documents/html.h"
#include "draw/drawing.h"
#include "io/writer.h"

namespace fl::jobs {

// "all" or a comma-separated list of model names (InputError for an unknown or empty name).
std::vector<fresnel::Model> parse_models(const std::string& list);

struct PlotRequest {
  std::string figure;  // strip | curves
  std::vector<std::string> materials;
  std::string models, params = "derived", out;
};
// InputError for an output type (.png, .svg or .pdf), parameter set or model list that
// does not exist, checked before any work.
void check_plot_request(const PlotRequest& request);
// The figure of `m` with the request's models and parameter set, as request.out, its labels in
// `font`.
io::Output plot_output(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                       const PlotRequest& request, const draw::LabelFont& font);

struct RenderRequest {
  std::vector<std::string> materials;
  std::string model = "schlick", params = "derived", out;
  std::string compare;  // a model list (parse_models): every model against the truth in one pass
  std::string env;      // a latitude-longitude .exr (empty: the analytic environment)
  std::string
      env_space;  // the environment's colour space (empty: its chromaticities, else lin_rec709)
  double env_rotate_deg = 0;
  double env_exposure_ev = 0;  // analysis::environment_map's exposure
  std::string flip = "webp";   // the flip's format with `compare`: webp or gif
  analysis::RenderSettings settings;
};
// `render --compare` renders at this size when --size is not given: flip frames 512 px wide.
constexpr int kCompareSizePx = 512;
// InputError for an output that is not .exr, an unknown model, model list, parameter set or flip
// format, or a roughness, size, sample or thread count out of range, checked before any work.
void check_render_request(const RenderRequest& request);
// FILE.exr (linear, premultiplied RGBA, the scene in its attributes) and FILE.png; with a model
// also FILE.truth.png and the ΔE2000 heat map FILE.de2000.png. With `compare`: FILE.exr holds
// the truth as R, G, B, A and each model as the layer MODEL.R, MODEL.G, MODEL.B with its heat map
// MODEL.de2000; FILE.truth.png, FILE.MODEL.png and FILE.MODEL.de2000.png per model (heat maps on
// one scale), the animated flip FILE.flip.webp (lossless; FILE.flip.gif with flip "gif": per
// model the truth, the model and its difference frame, draw/flip.h) and the contact sheet
// FILE.sheet.png. The heat maps, flip frames and sheet are labelled in
// `font`, which only a render that draws them needs (render_draws_labels; std::invalid_argument
// when it is null there).
// The pictures go through the context's display view (Context::display); the EXR and every
// ΔE2000 stay scene-linear.
io::Output render_output(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                         const RenderRequest& request, const draw::LabelFont* font);
// Whether the request draws labelled pictures (a model other than the truth, or a comparison).
bool render_draws_labels(const RenderRequest& request);

// Several materials write one output each: `out` must then hold "{name}", replaced per material by
// a file-safe form of its name (the catalog key, the page path or the file's stem, with characters
// other than letters, digits, '.', '-' and '_' turned into '_'); InputError otherwise.
std::string material_output(const std::string& out, const analysis::LoadedMaterial& m,
                            size_t count);
// plot_output / render_output for every material, to material_output paths (the pictures through
// the context's display view, Context::display).
io::Output plot_outputs(const analysis::Context& ctx,
                        const std::vector<analysis::LoadedMaterial>& ms, const PlotRequest& request,
                        const draw::LabelFont& font);
io::Output render_outputs(const analysis::Context& ctx,
                          const std::vector<analysis::LoadedMaterial>& ms,
                          const RenderRequest& request, const draw::LabelFont* font);

// The flip every gallery card of `reproduce` shows: figures/flip-KEY.png per material, the ground
// truth and then Schlick, F82 and Gulbrandsen (derived parameters) side by side, each a sphere of
// kFlipSizePx pixels at roughness kFlipRoughness under the analytic environment (rendered in one
// pass per material, materials in parallel).
constexpr int kFlipSizePx = 97;
constexpr double kFlipRoughness = 0.3;
constexpr int kFlipSamples = 32;
struct FlipFiles {
  io::Files files;
  std::vector<documents::Flip> flips;  // one per study, in order
};
FlipFiles reproduce_flips(const analysis::Context& ctx,
                          const std::vector<analysis::MaterialStudy>& studies);

// A gallery card of any material (a catalog entry, a database page, a file; no renders): name,
// class, page, the ground-truth colour strip (19 angles) and F0/F82 swatches, with the flags and
// facts given. What a preset library's gallery is made of.
documents::GalleryEntry material_card(const analysis::Context& ctx,
                                      const analysis::LoadedMaterial& m,
                                      std::vector<std::string> flags,
                                      std::vector<std::pair<std::string, std::string>> facts);

// material_card with the study's facts: the RMS ΔE2000 of Schlick, F82 and Gulbrandsen (derived
// parameters) and the best fitted model.
documents::GalleryEntry study_card(const analysis::Context& ctx, const analysis::MaterialStudy& st,
                                   std::vector<std::string> flags);

// A gallery card per study: name, class, page, ground-truth strip and F0/F82 swatches, flags (data
// extrapolated, presets outside [0, 1] from `presets`' out_of_range column, the F82 model's output
// clamp), the RMS ΔE2000 of Schlick, F82 and Gulbrandsen and the best fitted model; `figures` and
// `flips` (either may be empty) add the figure links and the flip.
std::vector<documents::GalleryEntry> catalog_gallery(
    const analysis::Context& ctx, const std::vector<analysis::MaterialStudy>& studies,
    const Table& presets, bool figures, const std::vector<documents::Flip>& flips);

// figures/strip-KEY.png and figures/curves-KEY.png per material (derived parameters), labelled in
// `font` and rendered in parallel, and their Markdown gallery as figures.md.
io::Files reproduce_figures(const analysis::Context& ctx,
                            const std::vector<analysis::MaterialStudy>& studies,
                            const draw::LabelFont& font);

}  // namespace fl::jobs
