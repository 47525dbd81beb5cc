// `plot strip | curves` and `render`: issue 7's pictures, and the figures `reproduce` writes.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>

#include "analysis/render.h"
#include "analysis/study.h"
#include "cli/app.h"
#include "report/exr.h"
#include "report/figures.h"
#include "report/png.h"
#include "report/writer.h"
#include "spectral/errors.h"
#include "util/parallel.h"

namespace fl::cli {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

std::string model_names() {
  std::string s;
  for (const auto& m : fresnel::model_specs()) s += (s.empty() ? "" : ", ") + std::string(m.name);
  return s;
}

// "all" or a comma-separated list of model names (InputError for unknown names).
std::vector<fresnel::Model> parse_models(const std::string& list) {
  std::vector<fresnel::Model> out;
  if (list == "all") {
    for (const auto& m : fresnel::model_specs()) out.push_back(m.model);
    return out;
  }
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    if (name.empty()) throw InputError(fmt::format("--models '{}': empty model name", list));
    const auto m = fresnel::model_from_name(name).model;
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
    start = end + 1;
  }
  return out;
}

void check_params_kind(const std::string& kind) {
  if (kind != "derived" && kind != "fitted")
    throw InputError(fmt::format("--params must be derived or fitted, not '{}'", kind));
}

// The study of one material (`one` holds it and must outlive the study, which points into it):
// fits only when fitted parameters are asked for.
analysis::MaterialStudy study_one(const analysis::Context& ctx, const std::vector<analysis::LoadedMaterial>& one,
                                  bool fit) {
  analysis::StudyOptions o;
  o.fit = fit;
  o.threads = 1;
  return analysis::study_materials(ctx, one, o).front();
}

report::FigureInput figure_input(const analysis::MaterialStudy& st, const std::vector<fresnel::Model>& models,
                                 const std::string& kind) {
  report::FigureInput in;
  in.material = st.material->material.name;
  in.parameter_kind = kind;
  in.ior = &st.material->ior;
  for (const auto m : models) {
    const auto& r = st.result(m);
    in.models.push_back({m, kind == "fitted" ? r.fitted.parameters : r.derived});
  }
  return in;
}

struct PlotArgs {
  std::string material, models, params = "derived", out;
};

void add_plot_subcommand(CLI::App& plot, GlobalOptions& g, Runner& selected, const char* name, const char* help,
                         const char* default_models, const char* out_help, bool svg_allowed) {
  auto* sub = plot.add_subcommand(name, help);
  auto a = std::make_shared<PlotArgs>();
  a->models = default_models;
  sub->add_option("MATERIAL", a->material, "catalog name, database page (main/Au/nk/Johnson) or file")->required();
  sub->add_option("--models", a->models, "comma-separated models, or all: " + model_names())->capture_default_str();
  sub->add_option("--params", a->params, "derived (from the spectral procedure) or fitted (Ceres)")
      ->capture_default_str();
  sub->add_option("--out", a->out, out_help)->required();
  const std::string which = name;
  sub->callback([&g, &selected, a, which, svg_allowed] {
    selected = [&g, a, which, svg_allowed] {
      const std::string ext = lower_extension(a->out);
      if (ext != ".png" && !(svg_allowed && ext == ".svg"))
        throw InputError(a->out, 0,
                         fmt::format("unknown output type '{}' (expected {})", ext.empty() ? "(none)" : ext,
                                     svg_allowed ? ".png, .svg" : ".png"));
      check_params_kind(a->params);
      const auto models = parse_models(a->models);
      const auto ctx = make_context(g);
      const std::vector<analysis::LoadedMaterial> one{
          analysis::load_material(ctx, spectral::resolve_material(a->material, g.settings.paths))};
      print_warnings(g, one);
      const auto st = study_one(ctx, one, a->params == "fitted");
      const auto in = figure_input(st, models, a->params);
      report::Font font;
      if (which == "strip") {
        report::write_png_atomic(a->out, report::strip_figure(ctx, in, font));
      } else {
        const auto d = report::curves_drawing(ctx, in);
        if (ext == ".svg") report::write_file_atomic(a->out, report::to_svg(d));
        else report::write_png_atomic(a->out, report::rasterize(d, font));
      }
      progress(g, fmt::format("plot {}: wrote {}", which, a->out));
      return 0;
    };
  });
}

struct RenderArgs {
  std::string material, model = "schlick", params = "derived", out;
  analysis::RenderSettings settings;
};

int run_render(const GlobalOptions& g, const RenderArgs& a) {
  if (lower_extension(a.out) != ".exr")
    throw InputError(a.out, 0, "the render output must be an .exr file (the PNGs are written beside it)");
  check_params_kind(a.params);
  const auto& rs = a.settings;
  if (!(rs.roughness >= 0.0 && rs.roughness <= 1.0))
    throw InputError(fmt::format("--roughness {} out of range (0 to 1)", rs.roughness));
  if (rs.size_px < 3 || rs.size_px > 4097) throw InputError(fmt::format("--size {} out of range (3 to 4097)", rs.size_px));
  if (rs.samples < 1 || rs.samples > 65536) throw InputError(fmt::format("--samples {} out of range (1 to 65536)", rs.samples));
  if (rs.threads < 0) throw InputError(fmt::format("--threads {} must be 0 (all) or positive", rs.threads));
  const bool truth_only = a.model == "truth";
  const fresnel::ModelSpec* spec = truth_only ? nullptr : &fresnel::model_from_name(a.model);

  const auto ctx = make_context(g);
  const std::vector<analysis::LoadedMaterial> one{
      analysis::load_material(ctx, spectral::resolve_material(a.material, g.settings.paths))};
  const auto& m = one.front();
  print_warnings(g, one);
  const auto env = analysis::default_environment();
  const auto t0 = std::chrono::steady_clock::now();
  const auto truth_table = analysis::truth_fresnel_table(ctx, m.ior, ctx.settings().eta_outside);
  const auto truth = analysis::render_sphere(env, truth_table, rs);
  analysis::SphereImage shown = truth;
  std::vector<double> params;
  if (!truth_only) {
    const auto st = study_one(ctx, one, a.params == "fitted");
    const auto& r = st.result(spec->model);
    params = a.params == "fitted" ? r.fitted.parameters : r.derived;
    shown = analysis::render_sphere(env, analysis::model_fresnel_table(spec->model, params), rs);
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress(g, fmt::format("render: {} × {} px, roughness {:g}, {} samples per strategy ({:.2f} s)", rs.size_px,
                          rs.size_px, rs.roughness, rs.samples, secs));

  // Output files: FILE.exr (linear, premultiplied RGBA) and FILE.png; with a model also
  // FILE.truth.png and the ΔE2000 heat map FILE.de2000.png.
  const std::string base = a.out.substr(0, a.out.size() - 4);
  const std::string label = truth_only ? std::string("spectral ground truth")
                                       : fmt::format("{} ({} parameters)", spec->name, a.params);
  report::ExrImage exr;
  exr.width = shown.width;
  exr.height = shown.height;
  exr.channels = {"R", "G", "B", "A"};
  exr.pixels.resize(static_cast<size_t>(exr.width) * exr.height * 4);
  for (size_t k = 0; k < shown.alpha.size(); ++k) {
    for (int c = 0; c < 3; ++c) exr.pixels[4 * k + c] = shown.rgb[3 * k + c];
    exr.pixels[4 * k + 3] = shown.alpha[k];
  }
  std::string param_text;
  if (spec) {
    const auto names = spec->param_names();
    for (size_t i = 0; i < names.size(); ++i) param_text += fmt::format("{}{}={:.6f}", i ? " " : "", names[i], params[i]);
  }
  exr.string_attributes = {
      {"fresnelLab:material", m.material.name},
      {"fresnelLab:fresnel", label},
      {"fresnelLab:parameters", param_text},
      {"fresnelLab:colorSpace", fmt::format("{} (linear), illuminant {}", ctx.settings().space, ctx.settings().illuminant)},
      {"fresnelLab:scene",
       "unit sphere, orthographic camera along -z, GGX specular only (analysis/render.h); environment: "
       "analytic sky + 18 deg key-light disc containing the view axis (default_environment)"}};
  exr.float_attributes = {{"fresnelLab:roughness", static_cast<float>(rs.roughness)},
                          {"fresnelLab:samples", static_cast<float>(rs.samples)}};

  report::Font font;
  std::vector<std::pair<std::string, std::string>> pngs;  // path, bytes
  pngs.emplace_back(base + ".png", report::encode_png(report::sphere_display(ctx, shown)));
  std::vector<double> de;
  if (!truth_only) {
    pngs.emplace_back(base + ".truth.png", report::encode_png(report::sphere_display(ctx, truth)));
    de = analysis::de2000_image(ctx, truth, shown);
    pngs.emplace_back(base + ".de2000.png",
                      report::encode_png(report::heatmap_figure(
                          de, shown.width, shown.height,
                          fmt::format("{}: ΔE2000, truth vs {}", m.material.name, spec->name), font)));
  }
  std::vector<std::string> written;
  try {
    report::write_exr_atomic(a.out, exr);
    written.push_back(a.out);
    for (const auto& [path, bytes] : pngs) {
      report::write_file_atomic(path, bytes);
      written.push_back(path);
    }
  } catch (...) {
    for (const auto& w : written) std::filesystem::remove(w);
    throw;
  }
  const int c = (rs.size_px / 2) * rs.size_px + rs.size_px / 2;
  progress(g, fmt::format("render: centre pixel ({:.5f}, {:.5f}, {:.5f})", shown.rgb[3 * c], shown.rgb[3 * c + 1],
                          shown.rgb[3 * c + 2]));
  if (!de.empty()) {
    double sum = 0, mx = 0;
    int n = 0;
    for (double v : de)
      if (std::isfinite(v)) sum += v, mx = std::max(mx, v), ++n;
    progress(g, fmt::format("render: ΔE2000 truth vs {}: mean {:.3f}, max {:.3f} over {} pixels", spec->name,
                            n ? sum / n : 0.0, mx, n));
  }
  std::string list;
  for (const auto& w : written) list += (list.empty() ? "" : ", ") + w;
  progress(g, "render: wrote " + list);
  return 0;
}

}  // namespace

void add_plot(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* plot = app.add_subcommand("plot", "figures: strip (colour strips) | curves (reflectance and ΔE2000 plots)");
  plot->require_subcommand(1);
  add_plot_subcommand(*plot, g, selected, "strip",
                      "stacked colour strips over 0°–90° and 80°–90°: ground truth and each model (sRGB via OCIO)",
                      "all", "output file (.png)", false);
  add_plot_subcommand(*plot, g, selected, "curves",
                      "R, G, B reflectance against angle (truth and models) and ΔE2000 against angle",
                      "schlick,f82,gulbrandsen", "output file (.png or .svg)", true);
}

void add_render(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "render",
      "a GGX sphere under an analytic sky and key light: FILE.exr and FILE.png; with a model also FILE.truth.png "
      "and the ΔE2000 heat map FILE.de2000.png");
  auto a = std::make_shared<RenderArgs>();
  sub->add_option("MATERIAL", a->material, "catalog name, database page (main/Au/nk/Johnson) or file")->required();
  sub->add_option("--model", a->model, "truth (spectral ground truth) or a model: " + model_names())
      ->capture_default_str();
  sub->add_option("--params", a->params, "derived or fitted model parameters")->capture_default_str();
  sub->add_option("--roughness", a->settings.roughness, "GGX perceptual roughness (0: perfect mirror)")
      ->capture_default_str();
  sub->add_option("--size", a->settings.size_px, "image width and height in pixels (odd: a pixel at the centre)")
      ->capture_default_str();
  sub->add_option("--samples", a->settings.samples, "samples per strategy per shading point")->capture_default_str();
  sub->add_option("--threads", a->settings.threads, "worker threads (0: all cores)")->capture_default_str();
  sub->add_option("--out", a->out, "output .exr (PNGs are written beside it)")->required();
  sub->callback([&g, &selected, a] { selected = [&g, a] { return run_render(g, *a); }; });
}

// The figures `reproduce` writes: figures/strip-KEY.png and figures/curves-KEY.png per material
// (derived parameters), rendered in parallel (one Font per material), plus a Markdown gallery.
std::vector<std::pair<std::string, std::string>> reproduce_figures(const GlobalOptions& g, const analysis::Context& ctx,
                                                                   const std::vector<analysis::MaterialStudy>& studies,
                                                                   std::string& gallery_md) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto all = parse_models("all");
  const auto curve_models = parse_models("schlick,f82,gulbrandsen");
  const size_t n = studies.size();
  std::vector<std::string> strips(n), curves(n);
  parallel_for(n, [&](size_t i) {
    report::Font font;
    strips[i] = report::encode_png(report::strip_figure(ctx, figure_input(studies[i], all, "derived"), font));
    curves[i] = report::encode_png(
        report::rasterize(report::curves_drawing(ctx, figure_input(studies[i], curve_models, "derived")), font));
  });

  std::vector<std::pair<std::string, std::string>> files;
  gallery_md =
      "# Figures\n\nGenerated by `fresnel-lab reproduce` (derived parameters). Per material: the colour strips "
      "(ground truth and every model over 0°–90° and 80°–90°, with each model's RMS ΔE2000) and the reflectance / "
      "ΔE2000 curves for Schlick, F82 and Gulbrandsen. Single figures: `fresnel-lab plot strip|curves MATERIAL`; "
      "sphere renders: `fresnel-lab render MATERIAL --model M --out FILE.exr`.\n\n";
  for (size_t i = 0; i < n; ++i) {
    const auto& mat = studies[i].material->material;
    const std::string strip = "figures/strip-" + mat.key + ".png", curve = "figures/curves-" + mat.key + ".png";
    files.emplace_back(strip, std::move(strips[i]));
    files.emplace_back(curve, std::move(curves[i]));
    gallery_md += fmt::format("## {}\n\n![{} colour strips]({})\n\n![{} curves]({})\n\n", mat.name, mat.name, strip,
                              mat.name, curve);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress(g, fmt::format("reproduce: figures ({} PNGs, {:.2f} s)", files.size(), s));
  return files;
}

}  // namespace fl::cli
