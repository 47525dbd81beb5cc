#include "documents/gltf.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "analysis/tables/shading_presets.h"
#include "analysis/tables/tables.h"
#include "documents/json.h"
#include "util/errors.h"

namespace fl::report {
namespace {

constexpr const char* kCoveragePolicy =
    "Each material's extras state its data source; coverage, the share of 360-830 nm (weighted by "
    "the illuminant × ȳ) that the data measures, for n and k together and each alone (coverage_k "
    "null without k data); and extrapolated: true when the nearest measured value is held "
    "somewhere, with the held range in uncovered (a colour computed there is not measured).";

Json rgb_array(const color::Rgb& v) {
  return Json::array({v.r, v.g, v.b});
}

// What a material stores for `value` (a colour glTF holds in [0, 1]) and what it says about it.
struct StoredColor {
  color::Rgb value;
  Json extras = Json::object();
};
StoredColor stored_color(const analysis::Context& ctx, const std::string& name,
                         const color::Rgb& v) {
  analysis::NamedValues named;
  analysis::add_channels(named, name, v);
  const std::string flags = analysis::out_of_range_list(named);
  if (flags.empty()) return {v, Json::object()};
  const auto unit = analysis::into_unit_range(ctx, v);
  return {unit.value,
          Json{{name, rgb_array(v)}, {"out_of_range", flags}, {"de00_stored", unit.de00}}};
}

Json dielectric(const analysis::ShadingPreset& p, Json& extras, std::set<std::string>& used) {
  Json pbr{{"baseColorFactor", p.clear ? Json::array({1, 1, 1, 1}) : Json::array({0, 0, 0, 1})},
           {"metallicFactor", 0}};
  Json ext{{"KHR_materials_ior", {{"ior", p.ior}}}};
  const double s = (p.ior - 1) / (p.ior + 1), f0_of_ior = s * s;
  color::Rgb tint;
  for (int c = 0; c < 3; ++c) tint[c] = p.f0[c] / f0_of_ior;
  if (std::max({std::abs(tint.r - 1), std::abs(tint.g - 1), std::abs(tint.b - 1)}) >
      kSpecularColorMin)
    ext["KHR_materials_specular"] = {{"specularColorFactor", rgb_array(tint)}};
  if (p.clear) ext["KHR_materials_transmission"] = {{"transmissionFactor", 1}};
  for (auto it = ext.begin(); it != ext.end(); ++it) used.insert(it.key());
  extras["f0"] = rgb_array(p.f0);
  return Json{{"pbrMetallicRoughness", std::move(pbr)}, {"extensions", std::move(ext)}};
}

Json material(const analysis::Context& ctx, const analysis::MaterialStudy& s,
              std::set<std::string>& used) {
  const auto p = analysis::shading_preset(ctx, s);
  const auto& c = s.material->coverage;
  Json extras{{"source", s.material->material.source},
              {"coverage", c.both},
              {"coverage_n", c.n},
              {"coverage_k", c.k},  // NaN (written as null) without k data
              {"extrapolated", c.extrapolated}};
  if (c.extrapolated) extras["uncovered"] = c.uncovered;
  Json m{{"name", s.material->material.name}};
  if (p.metal) {
    auto base = stored_color(ctx, "f0", p.f0);
    Json color = rgb_array(base.value);
    color.push_back(1);
    m["pbrMetallicRoughness"] = {{"baseColorFactor", std::move(color)}, {"metallicFactor", 1}};
    extras.update(base.extras);
  } else {
    m.update(dielectric(p, extras, used));
  }
  m["extras"] = {{"fresnelLab", std::move(extras)}};
  return m;
}

}  // namespace

std::string presets_gltf(const analysis::Context& ctx,
                         const std::vector<analysis::MaterialStudy>& studies) {
  if (ctx.space().builtin_equivalent != "lin_rec709")
    throw InputError(fmt::format(
        "glTF materials are linear Rec.709 (sRGB primaries, D65), not {}: use --space lin_rec709",
        ctx.settings().space));
  std::set<std::string> used;
  Json materials = Json::array();
  for (const auto& s : studies) materials.push_back(material(ctx, s, used));
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
  if (!used.empty())
    doc["extensionsUsed"] = Json(std::vector<std::string>(used.begin(), used.end()));
  doc["materials"] = std::move(materials);
  return write_json(doc, [](const std::string& key) {
    return key == "de00_stored" || key.rfind("coverage", 0) == 0 ? 4 : 6;
  });
}

}  // namespace fl::report
