#include "analysis/tables/table_registry.h"

#include <fmt/format.h>

#include "analysis/lut/lut.h"
#include "analysis/lut/lut_accuracy.h"
#include "analysis/pipeline/materials.h"
#include "analysis/presets/preset_tables.h"
#include "analysis/speed/speed.h"
#include "analysis/tables/averages.h"
#include "analysis/tables/table_layouts.h"
#include "analysis/tables/tables.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/suggest.h"

namespace fl::analysis {

const std::vector<MaterialStudy>& TableInputs::studies() {
  if (!studies_) studies_ = study_materials(ctx, materials, StudyOptions{}, study_progress_);
  return *studies_;
}

const PageStudies& TableInputs::group_pages() {
  if (!group_pages_) group_pages_ = study_pages(ctx, group_globs(materials));
  return *group_pages_;
}

const std::vector<ShadingPoint>& TableInputs::lut_points() {
  if (!lut_points_) lut_points_ = lut_accuracy_points();
  return *lut_points_;
}

const RenderedLibrary& TableInputs::rendered_library() {
  if (!rendered_library_) {
    LoadPolicy policy;
    policy.only = std::nullopt;
    const auto set = load_materials(ctx, {"**"}, policy);
    rendered_library_ = analysis::rendered_library(ctx, set.materials, lut_points());
  }
  return *rendered_library_;
}

void TableInputs::prepare() {
  lut_points();
  // The three inputs the tables share, computed side by side.
  parallel_for(3, [this](size_t i) {
    if (i == 0)
      studies();
    else if (i == 1)
      group_pages();
    else
      rendered_library();
  });
}

namespace {

Table rendered_library_of(TableInputs& in) {
  return rendered_library_table(
      in.ctx, in.rendered_library(),
      rendered_library_rows(in.rendered_library(),
                            load_gpu_costs(in.ctx.settings().paths.gpu_costs)));
}

Table speed_of(TableInputs& in) {
  const auto& paths = in.ctx.settings().paths;
  return speed_table(in.ctx, in.studies(), load_model_costs(paths.model_costs),
                     load_gpu_costs(paths.gpu_costs));
}

}  // namespace

const std::vector<TableSpec>& table_specs() {
  static const std::vector<TableSpec> specs{
      {"schlick", "Schlick (spectral F0) against spectral ground truth, every catalog material",
       [](TableInputs& in) { return schlick_table(in.ctx, in.materials); }},
      {"methods",
       "the talk's ways to derive RGB parameters (point sampling, reflectance processing, "
       "fitting), metals",
       [](TableInputs& in) { return methods_table(in.ctx, in.studies()); }},
      {"models", "every Fresnel model with derived and fitted parameters, every catalog material",
       [](TableInputs& in) { return models_table(in.ctx, in.studies()); }},
      {"averages",
       "hemispherical averages F_avg of every model, derived and fitted, against the ground truth "
       "(Kulla–Conty)",
       [](TableInputs& in) { return averages_table(in.ctx, in.studies()); }},
      {"blend",
       "parameter blending of Gulbrandsen (F0, g) against blending its results, every pair of "
       "metals",
       [](TableInputs& in) { return blend_table(in.ctx, in.studies(), in.blend); }},
      {"blend_models", "parameter blending for every model",
       [](TableInputs& in) { return blend_models_table(in.ctx, in.studies(), in.blend); }},
      {"gamut",
       "gamut conversion of Gulbrandsen parameters against converting results (Rec.709, AP0)",
       [](TableInputs& in) { return gamut_table(in.ctx, in.studies()); }},
      {"gamut_models", "gamut conversion for every model",
       [](TableInputs& in) { return gamut_models_table(in.ctx, in.studies()); }},
      {"media", "external media: exact against Schlick with adjusted F0, every material in 7 media",
       [](TableInputs& in) { return media_table(in.ctx, in.studies()); }},
      {"internal",
       "internal reflection of dielectrics: exact against Schlick with the transmission angle",
       [](TableInputs& in) { return internal_table(in.ctx, in.studies()); }},
      {"presets", "F0, F82, g, eta, kappa per material in the working space",
       [](TableInputs& in) { return presets_table(in.ctx, in.studies()); }},
      {"presets_openpbr",
       "OpenPBR Surface parameters per material: metals F0 and F82 tint, dielectrics specular_ior "
       "and transmission",
       [](TableInputs& in) { return openpbr_table(in.ctx, in.studies()); }},
      {"spread",
       "the spread between database pages of the same metal: F0, F82 colours and Schlick errors",
       [](TableInputs& in) { return spread_table(in.ctx, in.group_pages().studies); }},
      {"talk_spread", "the talk's Schlick values against the spread of each metal's database pages",
       [](TableInputs& in) {
         return talk_misses_table(in.ctx, in.materials, in.group_pages().studies);
       }},
      {"lut-accuracy",
       "every model (derived, fitted, fitted to the render) as rendered under IBL (DFG) and area "
       "lights (LTC moments) against brute-force spectral integration",
       [](TableInputs& in) { return lut_accuracy_table(in.ctx, in.studies(), in.lut_points()); }},
      {"lut-layouts", "DFG table layouts (size, placement, storage; Filament's, UE4's): own error",
       [](TableInputs& in) { return table_layouts_table(in.ctx, in.studies()); }, false},
      {"rendered-library",
       "rendered error of the shippable pre-integrated shaders (Schlick, F82, the basis at K = 2 "
       "to 5) over every database page, against K and the GPU cost",
       rendered_library_of},
      {"speed",
       "every model's cost per evaluation (committed benchmark costs) against its ΔE2000 error, "
       "Pareto front",
       speed_of},
  };
  return specs;
}

const TableSpec& find_table(const std::string& name) {
  std::vector<NameChoice> choices;
  for (const auto& t : table_specs()) choices.push_back({t.name, {}});
  if (const auto match = match_name(name, choices))
    for (const auto& t : table_specs())
      if (*match == t.name) return t;
  throw InputError(unknown_name_message("table", name, choices));
}

}  // namespace fl::analysis
