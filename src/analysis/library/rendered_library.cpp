#include "analysis/library/rendered_library.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/lut/rendered_fit.h"
#include "fresnel/projection.h"
#include "fresnel/registered_models.h"
#include "util/parallel.h"
#include "util/quantile.h"

namespace fl::analysis {
namespace {

using fresnel::Model;

Model model_named(const char* name) {
  return fresnel::model_from_name(name).model;
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
  std::vector<size_t> page;
  for (size_t i = 0; i < lib.pages.size(); ++i) {
    if (!in_class(lib.classes[i], page_class)) continue;
    const double e = lib.rms[i][shader][lighting];
    v.push_back(e);
    page.push_back(i);
    row.worse_than_f82 += e > lib.rms[i][f82][lighting];
  }
  row.pages = static_cast<int>(v.size());
  if (v.empty()) return row;
  for (const size_t k : largest_indices(v, kWorstPages)) {
    row.worst_pages.push_back(lib.pages[page[k]]);
    row.worst_values.push_back(v[k]);
  }
  row.median = median(v);
  row.p90 = quantile(v, 0.9);
  row.p99 = quantile(v, 0.99);
  row.max = quantile(v, 1.0);
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
  for (const char* cls : {"metal", "dielectric", "all"})
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

// "page (0.123), page (0.101), ..." of a row's tail.
std::string worst_list(const RenderedLibraryRow& r) {
  std::string out;
  for (size_t i = 0; i < r.worst_pages.size(); ++i)
    out += fmt::format("{}{} ({:.3f})", i ? "; " : "", r.worst_pages[i], r.worst_values[i]);
  return out;
}

// Per class (metals, dielectrics, then every page): median / p99 per shader under IBL and area.
std::string class_reading(const std::vector<RenderedLibraryRow>& rows, const char* cls,
                          const char* label) {
  const auto* first = find_row(rows, "schlick", Lighting::Ibl, cls);
  if (!first) return "";
  std::string out = fmt::format(" {} ({} pages), IBL then area:", label, first->pages);
  for (const char* s : {"schlick", "f82", "f82 rendered", "basis3", "basis4", "basis5"}) {
    const auto* ibl = find_row(rows, s, Lighting::Ibl, cls);
    const auto* area = find_row(rows, s, Lighting::Area, cls);
    if (ibl && area)
      out += fmt::format(" {} {:.3f} / {:.3f}, {:.3f} / {:.3f};", s, ibl->median, ibl->p99,
                         area->median, area->p99);
  }
  out.back() = '.';
  return out;
}

// The classes first (the dielectrics outnumber the metals six to one, so every page's figures are
// theirs), the pages worse than F82, and basis4's worst pages per class.
std::string library_reading(const std::vector<RenderedLibraryRow>& rows) {
  std::string out = "Median / p99 RMS ΔE2000 (nearest rank).";
  out += class_reading(rows, "metal", "Metals");
  out += class_reading(rows, "dielectric", "Dielectrics");
  out += class_reading(rows, "all", "Every page");
  for (const char* s : {"basis4", "basis5"})
    for (const Lighting l : {Lighting::Ibl, Lighting::Area})
      if (const auto* r = find_row(rows, s, l, "all"))
        out += fmt::format(" {} renders worse than F82 derived on {} of {} pages under {}.", s,
                           r->worse_than_f82, r->pages, lighting_name(l));
  for (const char* cls : {"metal", "dielectric"})
    if (const auto* r = find_row(rows, "basis4", Lighting::Ibl, cls))
      out += fmt::format(" basis4's worst {} {}s under IBL: {}.", r->worst_pages.size(), cls,
                         worst_list(*r));
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
               {"worst_pages"}};
  for (const auto& r : rows)
    t.rows.push_back({r.page_class, std::string(lighting_name(r.lighting)), r.shader->name,
                      static_cast<long long>(r.shader->terms), cost_cell(r.gpu, false),
                      cost_cell(r.gpu, true), static_cast<long long>(r.pages), r.median, r.p90,
                      r.p99, r.max, static_cast<long long>(r.worse_than_f82), worst_list(r)});
  t.reading = library_reading(rows);
  const auto& s = ctx.settings();
  t.notes = {
      fmt::format("Pages: every database page `library --class all` keeps ({} pages: covering "
                  "the visible range, n and k readable). Working space {}, illuminant {}.",
                  lib.pages.size(), s.space, s.illuminant),
      "Per page, the RMS ΔE2000 over lut-accuracy's shading points (the default roughness set × "
      "the view angles) between the engine's result from the 64² tables and the lobe integrated "
      "with the spectral ground truth; median, p90, p99 and max of those over the pages of the "
      "class, by nearest rank (the value of rank ⌈q·n⌉ in ascending order). Rows: metals, "
      "dielectrics, then every page (whose figures are mostly the dielectrics').",
      "Shaders: schlick and f82 with derived parameters (spectral F0, F82); f82 rendered: F82 "
      "fitted to the render from the derived set; basis2: the ground-truth curve projected on "
      "the basis's first two functions {1, b1} (no shader of its own); basis3 to basis5: the "
      "basis models' projections. terms: K, the table terms the shader weighs.",
      "gpu_instructions, texture_fetches: the shader's SPIR-V cost under that lighting "
      "(bench/gpu_costs.csv); unmeasured where no row exists. worse_than_f82: pages where the "
      "shader renders worse than F82 derived; worst_pages: the class's five worst pages, worst "
      "first, with their RMS (the tail by name: over a few hundred pages p99 is the 4th "
      "worst)."};
  return t;
}

}  // namespace fl::analysis
