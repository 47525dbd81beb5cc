#include "documents/gltf.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "analysis/presets/shading_presets.h"
#include "analysis/study/table_notes.h"
#include "color/matrix.h"
#include "documents/json.h"

namespace fl::documents {
namespace {

constexpr const char* kCoveragePolicy =
    "Each material's extras state its data source; coverage, the share of 360-830 nm (weighted by "
    "the illuminant × ȳ) that the data measures, for n and k together and each alone (coverage_k "
    "null without k data); and extrapolated: true when the nearest measured value is held "
    "somewhere, with the held range in uncovered (a colour computed there is not measured).";

// glTF's colours are linear Rec.709: values in any other working space are converted.
struct GltfSpace {
  bool converted = false;
  color::Mat3 from_working, to_working;
  std::string note;
};
GltfSpace gltf_space(const analysis::Context& ctx) {
  if (ctx.space().builtin_equivalent == "lin_rec709") return {};
  const std::string& space = ctx.settings().space;
  const color::Mat3 m = ctx.spaces().conversion_to_builtin(space, "lin_rec709");
  return {true, m, m.inverse(),
          fmt::format("glTF's colours are linear Rec.709: converted from {} with OpenColorIO's "
                      "matrix; ΔE2000 is measured in {}",
                      space, space)};
}

Json rgb_array(const color::Rgb& v) {
  return Json::array({v.r, v.g, v.b});
}

// What a material stores for `value` (a colour glTF holds in [0, 1]) and what it says about it.
struct StoredColor {
  color::Rgb value;
  Json extras = Json::object();
};
StoredColor stored_color(const analysis::Context& ctx, const GltfSpace& space,
                         const std::string& name, const color::Rgb& v) {
  analysis::NamedValues named;
  analysis::add_channels(named, name, v);
  const std::string flags = analysis::out_of_range_list(named);
  if (flags.empty()) return {v, Json::object()};
  const auto unit =
      analysis::into_unit_range(ctx, v, space.converted ? &space.to_working : nullptr);
  return {unit.value,
          Json{{name, rgb_array(v)}, {"out_of_range", flags}, {"de00_stored", unit.de00}}};
}

Json dielectric(const analysis::ShadingPreset& p, const color::Rgb& f0, Json& extras,
                std::set<std::string>& used) {
  Json pbr{{"baseColorFactor", p.clear ? Json::array({1, 1, 1, 1}) : Json::array({0, 0, 0, 1})},
           {"metallicFactor", 0}};
  Json ext{{"KHR_materials_ior", {{"ior", p.ior}}}};
  const double s = (p.ior - 1) / (p.ior + 1), f0_of_ior = s * s;
  color::Rgb tint;
  for (int c = 0; c < 3; ++c) tint[c] = f0[c] / f0_of_ior;
  if (std::max({std::abs(tint.r - 1), std::abs(tint.g - 1), std::abs(tint.b - 1)}) >
      kSpecularColorMin)
    ext["KHR_materials_specular"] = {{"specularColorFactor", rgb_array(tint)}};
  if (p.clear) ext["KHR_materials_transmission"] = {{"transmissionFactor", 1}};
  for (auto it = ext.begin(); it != ext.end(); ++it) used.insert(it.key());
  extras["f0"] = rgb_array(f0);
  return Json{{"pbrMetallicRoughness", std::move(pbr)}, {"extensions", std::move(ext)}};
}

// A consensus material's basis: its pages, their spread and each channel's range (working space).
Json consensus_extras(const analysis::ConsensusBasis& b, const std::string& space) {
  if (b.pages == 1) return Json{{"pages", 1}, {"single_page", true}};
  return Json{{"pages", b.pages},
              {"single_page", false},
              {"f0_de00_median", b.f0_median},
              {"f0_de00_max", b.f0_max},
              {"f82_de00_median", b.f82_median},
              {"f82_de00_max", b.f82_max},
              {"f0_lo", rgb_array(b.f0_lo)},
              {"f0_hi", rgb_array(b.f0_hi)},
              {"f82_lo", rgb_array(b.f82_lo)},
              {"f82_hi", rgb_array(b.f82_hi)},
              {"bounds_space", space}};  // the bounds stay in the working space
}

Json material(const analysis::Context& ctx, const GltfSpace& space,
              const analysis::MaterialStudy& s, double roughness, std::set<std::string>& used) {
  const auto p = analysis::shading_preset(ctx, s);
  const color::Rgb f0 = space.converted ? color::transform_rgb(space.from_working, p.f0) : p.f0;
  const auto& c = s.material->coverage;
  Json extras{{"source", s.material->material.source},
              {"coverage", c.both},
              {"coverage_n", c.n},
              {"coverage_k", c.k},  // NaN (written as null) without k data
              {"extrapolated", c.extrapolated}};
  if (c.extrapolated) extras["uncovered"] = c.uncovered;
  if (s.material->consensus)
    extras["consensus"] = consensus_extras(*s.material->consensus, ctx.settings().space);
  if (!s.material->resolved.empty()) extras["resolved"] = s.material->resolved;
  if (p.metal_form) extras["dielectric_form_de00"] = p.dielectric_form_de00;
  Json m{{"name", s.material->material.name}};
  if (p.metal) {
    auto base = stored_color(ctx, space, "f0", f0);
    Json color = rgb_array(base.value);
    color.push_back(1);
    m["pbrMetallicRoughness"] = {{"baseColorFactor", std::move(color)}, {"metallicFactor", 1}};
    extras.update(base.extras);
  } else {
    m.update(dielectric(p, f0, extras, used));
  }
  m["pbrMetallicRoughness"]["roughnessFactor"] = roughness;
  m["extras"] = {{"fresnelLab", std::move(extras)}};
  return m;
}

}  // namespace

std::string presets_gltf(const analysis::Context& ctx,
                         const std::vector<analysis::MaterialStudy>& studies,
                         const analysis::ExportOptions& options) {
  const GltfSpace space = gltf_space(ctx);
  std::set<std::string> used;
  Json materials = Json::array();
  for (const auto& s : studies)
    materials.push_back(material(ctx, space, s, options.roughness, used));
  const std::string policy = fmt::format(
      "Colours outside [0, 1] by more than {:g} cannot be stored: the colour of [0, 1]^3 nearest "
      "in ΔE2000 is, and the "
      "material's extras give the true value, its out_of_range list and the ΔE2000 the stored "
      "colour costs at normal "
      "incidence (de00_stored).",
      analysis::kOutOfRangeTolerance);
  Json doc{{"asset",
            {{"version", "2.0"},
             {"generator", "Fresnel Lab"},
             {"extras",
              {{"fresnelLab",
                {{"setting", analysis::setting_note(ctx)},
                 {"coverage_policy", kCoveragePolicy},
                 {"out_of_range_policy", policy}}}}}}}};
  if (space.converted) doc["asset"]["extras"]["fresnelLab"]["colour_space"] = space.note;
  doc["asset"]["extras"]["fresnelLab"]["roughness"] =
      fmt::format("perceptual roughness {:g} (alpha {:g}) for every material", options.roughness,
                  options.roughness * options.roughness);
  if (!options.skipped.empty()) doc["asset"]["extras"]["fresnelLab"]["skipped"] = options.skipped;
  if (!used.empty())
    doc["extensionsUsed"] = Json(std::vector<std::string>(used.begin(), used.end()));
  doc["materials"] = std::move(materials);
  return write_json(doc, [](const std::string& key) {
    return key == "de00_stored" || key.rfind("coverage", 0) == 0 ||
                   key.find("_de00") != std::string::npos
               ? 4
               : 6;
  });
}

}  // namespace fl::documents
