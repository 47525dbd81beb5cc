#include "jobs/pictures.h"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/lut/lut_accuracy.h"
#include "analysis/render/figure_data.h"
#include "draw/drawing.h"
#include "draw/figures.h"
#include "draw/png.h"
#include "util/errors.h"
#include "util/parallel.h"

namespace fl::jobs {
namespace {

analysis::FigureRequest figure_input(const analysis::MaterialStudy& st,
                                     const std::vector<fresnel::Model>& models,
                                     const std::string& kind) {
  analysis::FigureRequest in;
  in.material = st.material->material.name;
  in.parameter_kind = kind;
  in.ior = &st.material->ior;
  for (const auto m : models) in.models.push_back({m, analysis::model_params(st, m, kind)});
  return in;
}

draw::Drawing figure_drawing(const analysis::Context& ctx, const analysis::FigureRequest& in,
                             const std::string& figure) {
  return figure == "strip" ? draw::strip_drawing(analysis::strip_data(ctx, in))
                           : draw::curves_drawing(analysis::curve_data(ctx, in));
}

}  // namespace

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

void check_plot_request(const PlotRequest& r) {
  draw::file_type(r.out);
  analysis::parameter_set_from_name(r.params);
  parse_models(r.models);
}

io::Output plot_output(const analysis::Context& ctx, const analysis::LoadedMaterial& m,
                       const PlotRequest& r, const draw::LabelFont& font) {
  check_plot_request(r);
  const std::vector<analysis::LoadedMaterial> one{m};
  const auto models = parse_models(r.models);
  const auto st = analysis::study_one(ctx, one, r.params, models);
  io::Output o;
  const auto d = figure_drawing(ctx, figure_input(st, models, r.params), r.figure);
  o.files.emplace_back(r.out, draw::encode(d, draw::file_type(r.out), font));
  o.messages.push_back(fmt::format("plot {}: wrote {}", r.figure, r.out));
  return o;
}

std::string material_output(const std::string& out, const analysis::LoadedMaterial& m,
                            size_t count) {
  const auto at = out.find("{name}");
  if (at == std::string::npos) {
    if (count > 1)
      throw InputError(out, 0,
                       fmt::format("{} materials need '{{name}}' in --out (one file each)", count));
    return out;
  }
  const auto& mat = m.material;
  std::string name = mat.origin == spectral::Material::Origin::File ? mat.name : mat.key;
  for (auto& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return out.substr(0, at) + name + out.substr(at + 6);
}

io::Output plot_outputs(const analysis::Context& ctx,
                        const std::vector<analysis::LoadedMaterial>& ms, const PlotRequest& request,
                        const draw::LabelFont& font) {
  io::Output all;
  for (const auto& m : ms) {
    PlotRequest r = request;
    r.out = material_output(request.out, m, ms.size());
    auto o = plot_output(ctx, m, r, font);
    for (auto& f : o.files) all.files.push_back(std::move(f));
    for (auto& line : o.messages) all.messages.push_back(std::move(line));
  }
  return all;
}

io::Output render_outputs(const analysis::Context& ctx,
                          const std::vector<analysis::LoadedMaterial>& ms,
                          const RenderRequest& request, const draw::LabelFont* font) {
  io::Output all;
  for (const auto& m : ms) {
    RenderRequest r = request;
    r.out = material_output(request.out, m, ms.size());
    auto o = render_output(ctx, m, r, font);
    for (auto& f : o.files) all.files.push_back(std::move(f));
    for (auto& line : o.messages) all.messages.push_back(std::move(line));
  }
  return all;
}

io::Files reproduce_figures(const analysis::Context& ctx,
                            const std::vector<analysis::MaterialStudy>& studies,
                            const draw::LabelFont& font) {
  const auto all = parse_models("all");
  const auto curve_models = parse_models("schlick,f82,gulbrandsen");
  const size_t n = studies.size();
  std::vector<std::string> strips(n), curves(n);
  parallel_for(n, [&](size_t i) {
    strips[i] = draw::encode(figure_drawing(ctx, figure_input(studies[i], all, "derived"), "strip"),
                             draw::FileType::Png, font);
    curves[i] = draw::encode(
        figure_drawing(ctx, figure_input(studies[i], curve_models, "derived"), "curves"),
        draw::FileType::Png, font);
  });
  io::Files files;
  std::string gallery =
      "# Figures\n\nGenerated by `fresnel-lab reproduce` (derived parameters). Per material: the "
      "colour strips "
      "(ground truth and every model over 0°–90° and 80°–90°, with each model's RMS ΔE2000) and "
      "the reflectance / "
      "ΔE2000 curves for Schlick, F82 and Gulbrandsen. Single figures: `fresnel-lab plot "
      "strip|curves MATERIAL`; "
      "sphere renders: `fresnel-lab render MATERIAL --model M --out FILE.exr`.\n\n";
  for (size_t i = 0; i < n; ++i) {
    const auto& mat = studies[i].material->material;
    const std::string strip = "figures/strip-" + mat.key + ".png",
                      curve = "figures/curves-" + mat.key + ".png";
    files.emplace_back(strip, std::move(strips[i]));
    files.emplace_back(curve, std::move(curves[i]));
    gallery += fmt::format("## {}\n\n![{} colour strips]({})\n\n![{} curves]({})\n\n", mat.name,
                           mat.name, strip, mat.name, curve);
  }
  files.emplace_back("figures.md", gallery);
  return files;
}

FlipFiles reproduce_flips(const analysis::Context& ctx,
                          const std::vector<analysis::MaterialStudy>& studies) {
  const std::vector<fresnel::Model> models = parse_models("schlick,f82,gulbrandsen");
  analysis::RenderSettings rs;
  rs.size_px = kFlipSizePx;
  rs.roughness = kFlipRoughness;
  rs.samples = kFlipSamples;
  const analysis::SceneLight light = analysis::default_environment();
  const color::DisplayTransform& view = ctx.display();
  const size_t n = studies.size();
  std::vector<std::string> sprites(n);
  parallel_for(n, [&](size_t i) {
    std::vector<std::vector<double>> params;
    for (const auto m : models) params.push_back(analysis::model_params(studies[i], m, "derived"));
    const auto images =
        analysis::render_truth_and_models(ctx, *studies[i].material, light, models, params, rs);
    const auto backdrop = analysis::backdrop_for(studies[i].material->material.material_class);
    io::Image8 sprite(kFlipSizePx * static_cast<int>(images.size()), kFlipSizePx);
    for (size_t f = 0; f < images.size(); ++f) {
      const io::Image8 frame(kFlipSizePx, kFlipSizePx,
                             analysis::sphere_display(view, images[f], backdrop));
      for (int y = 0; y < kFlipSizePx; ++y)
        for (int x = 0; x < kFlipSizePx; ++x)
          sprite.set(static_cast<int>(f) * kFlipSizePx + x, y, frame.at(x, y));
    }
    sprites[i] = draw::encode_png(sprite);
  });
  FlipFiles out;
  for (size_t i = 0; i < n; ++i) {
    const auto& mat = studies[i].material->material;
    std::vector<std::string> labels{
        analysis::reflection_only(mat.material_class)
            ? fmt::format("ground truth (spectral; {})", analysis::kReflectionOnlyNote)
            : "ground truth (spectral)"};
    for (const auto m : models) labels.push_back(fresnel::model_spec(m).name);
    const std::string path = "figures/flip-" + mat.key + ".png";
    out.files.emplace_back(path, std::move(sprites[i]));
    out.flips.push_back({path, kFlipSizePx, labels});
  }
  return out;
}

namespace {

std::vector<std::string> card_flags(const analysis::MaterialStudy& st,
                                    const std::string& out_of_range) {
  std::vector<std::string> flags;
  if (st.material->coverage.extrapolated) flags.push_back("extrapolated");
  if (!out_of_range.empty()) flags.push_back("outside [0, 1]: " + out_of_range);
  if (st.result(fresnel::model_from_name("f82").model).derived_clamps)
    flags.push_back("F82 output clamped");
  return flags;
}

// The real index at `lambda_nm`, linear between the material's grid wavelengths.
double eta_at(const spectral::ComplexIorSpectrum& ior, double lambda_nm) {
  std::vector<double> x, n;
  for (int i = 0; i < ior.grid.count; ++i) {
    x.push_back(ior.grid.lambda_nm(i));
    n.push_back(ior.ior[static_cast<size_t>(i)].real());
  }
  return spectral::interpolate_linear(x, n, lambda_nm);
}

std::vector<std::pair<std::string, std::string>> card_facts(const analysis::MaterialStudy& st) {
  std::string derived;
  for (const auto m : parse_models("schlick,f82,gulbrandsen"))
    derived += fmt::format("{}{} {:.3f}", derived.empty() ? "" : " · ", fresnel::model_spec(m).name,
                           st.result(m).derived_error.rms);
  const analysis::ModelResult* best = &st.models.front();
  for (const auto& r : st.models)
    if (r.fitted_error.rms < best->fitted_error.rms) best = &r;
  std::vector<std::pair<std::string, std::string>> facts{
      {"RMS ΔE2000", derived},
      {"best fitted",
       fmt::format("{} {:.3f}", fresnel::model_spec(best->model).name, best->fitted_error.rms)}};
  if (st.material->material.material_class == spectral::MaterialClass::Dielectric)
    facts.emplace_back("η at 589 nm", fmt::format("{:.4f}", eta_at(st.material->ior, 589.0)));
  return facts;
}

io::Rgb8 rgb8(const std::uint8_t* p) {
  return {p[0], p[1], p[2]};
}

}  // namespace

documents::GalleryEntry material_card(const analysis::Context& ctx,
                                      const analysis::LoadedMaterial& m,
                                      std::vector<std::string> flags,
                                      std::vector<std::pair<std::string, std::string>> facts) {
  const auto& mat = m.material;
  const auto sw = analysis::material_swatches(ctx, m.ior);
  documents::GalleryEntry e;
  e.key = mat.key;
  e.name = mat.name;
  e.material_class = spectral::to_string(mat.material_class);
  e.source = mat.source;
  for (size_t k = 0; k + 2 < sw.strip.size(); k += 3) e.strip.push_back(rgb8(&sw.strip[k]));
  e.f0 = rgb8(sw.f0.data());
  e.f82 = rgb8(sw.f82.data());
  e.flags = std::move(flags);
  e.facts = std::move(facts);
  return e;
}

documents::GalleryEntry study_card(const analysis::Context& ctx, const analysis::MaterialStudy& st,
                                   std::vector<std::string> flags) {
  return material_card(ctx, *st.material, std::move(flags), card_facts(st));
}

std::vector<documents::GalleryEntry> catalog_gallery(
    const analysis::Context& ctx, const std::vector<analysis::MaterialStudy>& studies,
    const Table& presets, bool figures, const std::vector<documents::Flip>& flips) {
  std::vector<documents::GalleryEntry> out;
  const int col = column_index(presets, "out_of_range");
  for (size_t i = 0; i < studies.size(); ++i) {
    const auto& st = studies[i];
    const auto& mat = st.material->material;
    std::string out_of_range;
    for (const auto& row : presets.rows)
      if (std::get<std::string>(row[0]) == mat.name) out_of_range = std::get<std::string>(row[col]);
    documents::GalleryEntry e = study_card(ctx, st, card_flags(st, out_of_range));
    if (figures)
      e.figures = {{mat.name + " colour strips", "figures/strip-" + mat.key + ".png"},
                   {mat.name + " curves", "figures/curves-" + mat.key + ".png"}};
    if (i < flips.size()) e.flip = flips[i];
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace fl::jobs
