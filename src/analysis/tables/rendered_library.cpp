#include "analysis/tables/rendered_library.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/lut/rendered_fit.h"
#include "fresnel/projection.h"
#include "fresnel/registered_models.h"
#include "util/parallel.h"

namespace fl::analysis {
namespace {

using fresnel::Model;

Model model_named(const char* name) {
  return fresnel::model_from_name(name).model;
}

// The q-quantile by nearest rank on the sorted values (q = 0.5: the median of an odd count).
double quantile(const std::vector<double>& sorted, double q) {
  const double at = q * static_cast<double>(sorted.size() - 1);
  return sorted[static_cast<size_t>(std::lround(at))];
}

// The rendered fits' stop (fit::FitOptions::function_tolerance): F82's shading is linear in its
// parameters, and its fits from the derived sets, stopped once a step lowers ½ Σ ΔE2000² by less
// than 1e-6 of it, end within 3e-6 RMS ΔE2000 of the same fits run to 1e-10 over every database
// page (2,812 pages) in 31 % fewer iterations: no printed digit (1e-3) moves. lut-accuracy's fits
// keep the default: the models it fits that are not linear in their parameters (generalized
// Schlick, RGB η and κ) still gain 0.01–0.06 ΔE2000 after a step of that size.
constexpr double kLibraryFitTolerance = 1e-6;

// Per channel, the shader's weights on the table terms for one page.
std::array<fresnel::TableTerms, 3> shader_weights(const Context& ctx, const MaterialStudy& study,
                                                  const LibraryShader& s,
                                                  const std::vector<color::Rgb>& lobe,
                                                  const std::vector<ShadingPoint>& points) {
  std::array<fresnel::TableTerms, 3> w;
  if (!s.model) {
    const auto& mu = ctx.cos_thetas();
    std::vector<double> f(mu.size());
    for (int c = 0; c < 3; ++c) {
      for (size_t j = 0; j < mu.size(); ++j) f[j] = study.truth[j][c];
      w[c] = fresnel::project_on_terms(
          mu, f, std::span<const fresnel::Term>(fresnel::kBasisSpan).first(s.terms));
    }
    return w;
  }
  const auto& r = study.result(*s.model);
  auto params = r.derived;
  if (s.set == ParameterSet::Rendered) {
    const auto fit = fit_rendered(ctx, lobe, *s.model, points, {r.derived}, study.lossless,
                                  kLibraryFitTolerance);
    if (fit.usable) params = fit.parameters;
  }
  const auto& spec = fresnel::model_spec(*s.model);
  for (int c = 0; c < 3; ++c) w[c] = spec.table_terms(params.data(), c);
  return w;
}

}  // namespace

const std::vector<LibraryShader>& library_shaders() {
  static const std::vector<LibraryShader> shaders{
      {"schlick", model_named("schlick"), ParameterSet::Derived, 2},
      {"basis2", std::nullopt, ParameterSet::Derived, 2},
      {"f82", model_named("f82"), ParameterSet::Derived, 3},
      {"f82 rendered", model_named("f82"), ParameterSet::Rendered, 3},
      {"basis3", model_named("basis3"), ParameterSet::Derived, 3},
      {"basis4", model_named("basis4"), ParameterSet::Derived, 4},
      {"basis5", model_named("basis5"), ParameterSet::Derived, 5}};
  return shaders;
}

RenderedLibrary rendered_library(const Context& ctx, const std::vector<LoadedMaterial>& materials,
                                 const std::vector<ShadingPoint>& points) {
  StudyOptions options;
  options.fit = false;
  options.method_errors = false;
  options.derived_errors = false;  // the shaders read the derived parameters alone
  for (const auto& s : library_shaders())
    if (s.model &&
        std::find(options.models.begin(), options.models.end(), *s.model) == options.models.end())
      options.models.push_back(*s.model);
  std::sort(options.models.begin(), options.models.end(),
            [](Model a, Model b) { return a.index() < b.index(); });
  const auto studies = study_materials(ctx, materials, options);
  RenderedLibrary lib;
  lib.rms.resize(studies.size());
  for (const auto& s : studies) {
    lib.pages.push_back(s.material->material.name);
    lib.classes.push_back(s.material->material.material_class);
  }
  parallel_for(studies.size(), [&](size_t i) {
    const auto lobe = lobe_truth(ctx, *studies[i].material, points);
    const auto lobe_lab = lab_curve(ctx, lobe);
    for (const auto& s : library_shaders()) {
      const auto w = shader_weights(ctx, studies[i], s, lobe, points);
      lib.rms[i].push_back(
          {error_stats(rendered_de00_terms(ctx, lobe_lab, w, Lighting::Ibl, points)).rms,
           error_stats(rendered_de00_terms(ctx, lobe_lab, w, Lighting::Area, points)).rms});
    }
  });
  return lib;
}

namespace {

bool in_class(spectral::MaterialClass c, const std::string& page_class) {
  return page_class == "all" || page_class == spectral::to_string(c);
}

RenderedLibraryRow library_row(const RenderedLibrary& lib, size_t shader, int lighting,
                               const std::string& page_class, size_t f82) {
  RenderedLibraryRow row;
  row.shader = &library_shaders()[shader];
  row.lighting = lighting == 0 ? Lighting::Ibl : Lighting::Area;
  row.page_class = page_class;
  std::vector<double> v;
  for (size_t i = 0; i < lib.pages.size(); ++i) {
    if (!in_class(lib.classes[i], page_class)) continue;
    const double e = lib.rms[i][shader][lighting];
    v.push_back(e);
    row.worse_than_f82 += e > lib.rms[i][f82][lighting];
    if (e >= row.max) row.max = e, row.worst_page = lib.pages[i];
  }
  row.pages = static_cast<int>(v.size());
  if (v.empty()) return row;
  std::sort(v.begin(), v.end());
  row.median = quantile(v, 0.5);
  row.p90 = quantile(v, 0.9);
  row.p99 = quantile(v, 0.99);
  return row;
}

}  // namespace

std::vector<RenderedLibraryRow> rendered_library_rows(const RenderedLibrary& lib,
                                                      const GpuCosts& gpu) {
  const auto& shaders = library_shaders();
  const size_t f82 = static_cast<size_t>(
      std::find_if(shaders.begin(), shaders.end(), [](const auto& s) { return s.name == "f82"; }) -
      shaders.begin());
  std::vector<RenderedLibraryRow> rows;
  for (const char* cls : {"all", "metal", "dielectric"})
    for (int l = 0; l < 2; ++l)
      for (size_t s = 0; s < shaders.size(); ++s) {
        auto row = library_row(lib, s, l, cls, f82);
        if (row.pages == 0) continue;
        if (shaders[s].model) row.gpu = gpu.of(*shaders[s].model, row.lighting);
        rows.push_back(std::move(row));
      }
  return rows;
}

namespace {

std::string cost_cell(const std::optional<GpuCost>& g, bool texture) {
  if (!g) return "unmeasured";
  return fmt::format("{}", texture ? g->texture : g->instructions);
}

const RenderedLibraryRow* find_row(const std::vector<RenderedLibraryRow>& rows,
                                   const std::string& shader, Lighting l, const char* cls) {
  for (const auto& r : rows)
    if (r.shader->name == shader && r.lighting == l && r.page_class == cls) return &r;
  return nullptr;
}

// "basis4 under ibl: median 0.077, p99 0.210 (all pages); ..." and the pages worse than F82.
std::string library_reading(const std::vector<RenderedLibraryRow>& rows) {
  std::string out = "Median / p99 RMS ΔE2000 over every page:";
  for (const char* s : {"schlick", "f82", "f82 rendered", "basis3", "basis4", "basis5"})
    for (const Lighting l : {Lighting::Ibl, Lighting::Area})
      if (const auto* r = find_row(rows, s, l, "all"))
        out += fmt::format(" {} {} {:.3f} / {:.3f};", s, lighting_name(l), r->median, r->p99);
  out.back() = '.';
  for (const char* s : {"basis4", "basis5"})
    for (const Lighting l : {Lighting::Ibl, Lighting::Area})
      if (const auto* r = find_row(rows, s, l, "all"))
        out += fmt::format(" {} renders worse than F82 derived on {} of {} pages under {}.", s,
                           r->worse_than_f82, r->pages, lighting_name(l));
  return out;
}

}  // namespace

Table rendered_library_table(const Context& ctx, const RenderedLibrary& lib,
                             const std::vector<RenderedLibraryRow>& rows) {
  Table t;
  t.name = "rendered-library";
  t.title =
      "Rendered error over every database page against the number of table terms K and the GPU "
      "cost (ΔE2000)";
  t.columns = {{"class"},           {"lighting"},           {"shader"},
               {"terms"},           {"gpu_instructions"},   {"texture_fetches"},
               {"pages"},           {"median_rms_de00", 3}, {"p90_rms_de00", 3},
               {"p99_rms_de00", 3}, {"max_rms_de00", 3},    {"worse_than_f82"},
               {"worst_page"}};
  for (const auto& r : rows)
    t.rows.push_back({r.page_class, std::string(lighting_name(r.lighting)), r.shader->name,
                      static_cast<long long>(r.shader->terms), cost_cell(r.gpu, false),
                      cost_cell(r.gpu, true), static_cast<long long>(r.pages), r.median, r.p90,
                      r.p99, r.max, static_cast<long long>(r.worse_than_f82), r.worst_page});
  t.reading = library_reading(rows);
  const auto& s = ctx.settings();
  t.notes = {
      fmt::format("Pages: every database page `library --class all` keeps ({} pages: covering "
                  "the visible range, n and k readable). Working space {}, illuminant {}.",
                  lib.pages.size(), s.space, s.illuminant),
      "Per page, the RMS ΔE2000 over lut-accuracy's shading points (the default roughness set × "
      "the view angles) between the engine's result from the 64² tables and the lobe integrated "
      "with the spectral ground truth; median, p90, p99 and max of those over the pages of the "
      "class (nearest rank).",
      "Shaders: schlick and f82 with derived parameters (spectral F0, F82); f82 rendered: F82 "
      "fitted to the render from the derived set; basis2: the ground-truth curve projected on "
      "{1, (1 − μ)⁵} (Schlick's two channels with free weights, no shader of its own); basis3 to "
      "basis5: the basis models' projections. terms: K, the table terms the shader weighs.",
      "gpu_instructions, texture_fetches: the shader's SPIR-V cost under that lighting "
      "(bench/gpu_costs.csv); unmeasured where no row exists. worse_than_f82: pages where the "
      "shader renders worse than F82 derived; worst_page: the page with the max."};
  return t;
}

}  // namespace fl::analysis
