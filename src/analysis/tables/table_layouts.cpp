#include "analysis/tables/table_layouts.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "fresnel/registered_models.h"
#include "util/parallel.h"
#include "util/quantile.h"

namespace fl::analysis {

namespace {

// A texel-centre grid of n_nov × n_roughness texels whose row j holds roughness_of(j).
template <class RoughnessOf>
LutGrid centres_grid(int n_nov, int n_roughness, RoughnessOf roughness_of,
                     const std::string& convention) {
  LutGrid g;
  g.size = n_nov;
  for (int i = 0; i < n_nov; ++i) g.nov.push_back((i + 0.5) / n_nov);
  for (int j = 0; j < n_roughness; ++j) {
    const double r = roughness_of(j);
    g.perceptual_roughness.push_back(r);
    g.alpha.push_back(r * r);
  }
  g.placement = TexelPlacement::Centres;
  g.convention = convention;
  return g;
}

TableLayout ours(int size, TexelPlacement placement, TexelStorage storage) {
  const bool ends = placement == TexelPlacement::Endpoints;
  EngineTables t = engine_tables(size, storage);
  if (!ends) t.dfg = filament_dfg_grid(size);
  return {fmt::format("ours {}², {}, {}", size, ends ? "endpoints" : "texel centres",
                      texel_storage_name(storage)),
          ends ? "`lut dfg --size N`" : "`lut dfg --layout filament` (texel centres)", t};
}

}  // namespace

LutGrid cmgen_dfg_grid(int size) {
  return centres_grid(
      size, size, [size](int j) { return std::min(1.0, (j + 1.5) / size); },
      fmt::format("Filament cmgen: nov = (i + 0.5)/{0}, roughness = min(1, (j + 1.5)/{0})", size));
}

LutGrid ue4_dfg_grid() {
  return centres_grid(
      128, 32, [](int j) { return (j + 0.5) / 32; },
      "Unreal Engine 4: nov = (i + 0.5)/128, roughness = (j + 0.5)/32");
}

std::vector<TableLayout> table_layouts() {
  std::vector<TableLayout> out;
  for (const auto placement : {TexelPlacement::Centres, TexelPlacement::Endpoints})
    for (int size : {16, 32, 64, 128}) out.push_back(ours(size, placement, TexelStorage::Float));
  for (const auto placement : {TexelPlacement::Centres, TexelPlacement::Endpoints})
    out.push_back(ours(64, placement, TexelStorage::Half));
  EngineTables cmgen = engine_tables(128, TexelStorage::Half);
  cmgen.dfg = cmgen_dfg_grid(128);
  out.push_back({"Filament cmgen 128², half", "Filament libs/ibl CubemapIBL.cpp (DFG)", cmgen});
  EngineTables ue4 = engine_tables(128, TexelStorage::Unorm16);
  ue4.dfg = ue4_dfg_grid();
  out.push_back(
      {"UE4 128×32, unorm16", "Unreal Engine 4 SystemTextures.cpp (PreintegratedGF)", ue4, true});
  return out;
}

namespace {

struct LayoutErrors {
  std::vector<double> schlick, basis4;  // per metal: the tables' own RMS ΔE2000 under IBL
};

LayoutErrors layout_errors(const Context& ctx, const std::vector<const MaterialStudy*>& metals,
                           const std::vector<ShadingPoint>& points,
                           Lighting lighting = Lighting::Ibl) {
  const auto schlick = fresnel::model_from_name("schlick").model;
  const auto basis4 = fresnel::model_from_name("basis4").model;
  LayoutErrors e;
  e.schlick.resize(metals.size());
  e.basis4.resize(metals.size());
  parallel_for(metals.size(), [&](size_t k) {
    const auto& s = *metals[k];
    e.schlick[k] =
        error_stats(table_de00(ctx, schlick, s.result(schlick).derived, lighting, points)).rms;
    e.basis4[k] =
        error_stats(table_de00(ctx, basis4, s.result(basis4).derived, lighting, points)).rms;
  });
  return e;
}

// A cell the layout cannot fill (tables print NaN as n/a).
constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

double largest(const std::vector<double>& v) {
  return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

std::vector<const MaterialStudy*> metals_of(const std::vector<MaterialStudy>& studies) {
  std::vector<const MaterialStudy*> metals;
  for (const auto& s : studies)
    if (s.material->material.material_class == spectral::MaterialClass::Metal) metals.push_back(&s);
  return metals;
}

}  // namespace

TableErrorSummary table_error_summary(const Context& ctx, const std::vector<MaterialStudy>& studies,
                                      const EngineTables& tables, Lighting lighting) {
  const auto metals = metals_of(studies);
  const std::vector<double> roughness(kDefaultRoughness.begin(), kDefaultRoughness.end());
  const auto e = layout_errors(ctx, metals, shading_points(roughness, 0, tables), lighting);
  return {static_cast<int>(metals.size()), median(e.schlick), median(e.basis4), largest(e.basis4)};
}

Table table_layouts_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  Table t;
  t.name = "lut-layouts";
  t.title = "DFG table layouts: the tables' own error under IBL (ΔE2000, metals)";
  t.columns = {{"layout"},
               {"texels"},
               {"storage"},
               {"schlick_median_de00", 4},
               {"schlick_max_de00", 4},
               {"basis4_median_de00", 4},
               {"basis4_max_de00", 4},
               {"source"}};
  const auto metals = metals_of(studies);
  const std::vector<double> roughness(kDefaultRoughness.begin(), kDefaultRoughness.end());
  for (const auto& layout : table_layouts()) {
    const auto points = shading_points(roughness, 0, layout.tables);
    const auto e = layout_errors(ctx, metals, points);
    t.rows.push_back({layout.name,
                      fmt::format("{}×{}", layout.tables.dfg.nov.size(),
                                  layout.tables.dfg.perceptual_roughness.size()),
                      std::string(texel_storage_name(layout.tables.storage)), median(e.schlick),
                      largest(e.schlick), layout.schlick_only ? kNotApplicable : median(e.basis4),
                      layout.schlick_only ? kNotApplicable : largest(e.basis4), layout.source});
  }
  t.reading = fmt::format(
      "Over {} metals, per metal the RMS over lut-accuracy's shading points of ΔE2000 between the "
      "engine's IBL shading from the DFG table and from the exact lobe integrals at the point.",
      metals.size());
  t.notes = {
      "Texel centres hold (k + ½)/N and are read at uv = x: a read at roughness 1 clamps to the "
      "last texel, roughness 1 − ½/N, so the error falls only as 1/N. Endpoints hold k/(N − 1) "
      "and are read at uv = x·(N − 1)/N + ½/N: both ends are exact, and the error inside falls "
      "as 1/N² (bilinear interpolation).",
      "Storage: float rounds each texel to 32 bits, half to 11 significant bits (RGBA16F), "
      "unorm16 to k/65535.",
      "UE4's table holds Schlick's scale and bias only (its basis4 cells are n/a); Filament's "
      "and ours hold every term's channel."};
  return t;
}

}  // namespace fl::analysis
