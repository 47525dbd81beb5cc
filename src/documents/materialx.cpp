#include "documents/materialx.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "analysis/tables/shading_presets.h"
#include "analysis/tables/tables.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::report {

MaterialxShader materialx_shader_from_name(const std::string& name) {
  // MaterialX's node names; the short names people say for them are aliases.
  const std::vector<NameChoice> choices = {
      {"generalized_schlick", {"generalised_schlick", "generalized_schlick_bsdf"}},
      {"open_pbr_surface", {"openpbr", "open_pbr"}},
      {"standard_surface", {"autodesk_standard_surface"}}};
  const auto match = match_name(name, choices);
  if (!match) throw InputError("--shader: " + unknown_name_message("shader", name, choices));
  if (*match == "open_pbr_surface") return MaterialxShader::OpenPbrSurface;
  if (*match == "standard_surface") return MaterialxShader::StandardSurface;
  return MaterialxShader::GeneralizedSchlick;
}

const char* to_string(MaterialxShader s) {
  switch (s) {
    case MaterialxShader::GeneralizedSchlick:
      return "generalized_schlick";
    case MaterialxShader::OpenPbrSurface:
      return "open_pbr_surface";
    default:
      return "standard_surface";
  }
}

MaterialxSpace materialx_space(const analysis::Context& ctx) {
  const std::string& builtin = ctx.space().builtin_equivalent;
  if (builtin == "acescg" || builtin == "lin_rec709") return {builtin, {}, ""};
  if (builtin == "lin_p3d65") return {"lin_displayp3", {}, ""};
  const std::string& space = ctx.settings().space;
  return {"acescg", ctx.spaces().conversion_to_builtin(space, "acescg"),
          fmt::format(
              "MaterialX 1.39 has no colour space for {}: the colours are converted to acescg with "
              "OpenColorIO's matrix",
              space)};
}

namespace {

struct Writer {
  const MaterialxSpace& space;
  analysis::NamedValues
      flags;  // the colours written for the current material, by MaterialX input name

  std::string color(const std::string& input, const color::Rgb& working) {
    const color::Rgb v = color::transform_rgb(space.from_working, working);
    analysis::add_channels(flags, input, v);
    return fmt::format(
        "    <input name=\"{}\" type=\"color3\" value=\"{:.6f}, {:.6f}, {:.6f}\" />\n", input, v.r,
        v.g, v.b);
  }
  static std::string number(const std::string& input, double v) {
    return fmt::format("    <input name=\"{}\" type=\"float\" value=\"{:.6g}\" />\n", input, v);
  }
};

std::string xml_attribute(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::string node_id(const std::string& key) {
  std::string id = key;
  for (auto& ch : id)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "m_" + id;
  return id;
}

// The shader node (and for the generalized Schlick BSDF the `surface` over it), named id_shader.
// Inputs are appended one statement at a time so that `w.flags` lists them in document order.
std::string shader_nodes(const std::string& id, const analysis::ShadingPreset& p,
                         MaterialxShader shader, Writer& w) {
  std::string s;
  if (shader == MaterialxShader::GeneralizedSchlick) {
    s = fmt::format("  <generalized_schlick_bsdf name=\"{}_bsdf\" type=\"BSDF\">\n", id);
    s += w.color("color0", p.f0);
    s += w.color("color82", p.f82_tint);
    s += "    <input name=\"color90\" type=\"color3\" value=\"1, 1, 1\" />\n";
    if (p.clear) s += "    <input name=\"scatter_mode\" type=\"string\" value=\"RT\" />\n";
    return s +
           fmt::format(
               "  </generalized_schlick_bsdf>\n  <surface name=\"{0}_shader\" "
               "type=\"surfaceshader\">\n"
               "    <input name=\"bsdf\" type=\"BSDF\" nodename=\"{0}_bsdf\" />\n  </surface>\n",
               id);
  }
  const bool open_pbr = shader == MaterialxShader::OpenPbrSurface;
  const char* node = open_pbr ? "open_pbr_surface" : "standard_surface";
  s = fmt::format("  <{} name=\"{}_shader\" type=\"surfaceshader\">\n", node, id);
  s += w.number(open_pbr ? "base_metalness" : "metalness", p.metal ? 1 : 0);
  if (p.metal) {
    if (!open_pbr)
      s += w.number(
          "base", 1);  // Standard Surface's reflectivity is base · base_color (base 0.8 by default)
    s += w.color("base_color", p.f0);
    s += w.color("specular_color", open_pbr ? p.f82_tint : p.edge_tint);
  } else {
    s += w.number(open_pbr ? "specular_ior" : "specular_IOR", p.ior);
    if (p.clear) s += w.number(open_pbr ? "transmission_weight" : "transmission", 1);
    if (!p.clear) s += w.number(open_pbr ? "base_weight" : "base", 0);
  }
  return s + fmt::format("  </{}>\n", node);
}

// What a material's data is and how much of the visible range it measures, for its doc attribute.
std::string provenance(const analysis::LoadedMaterial& m) {
  const auto& c = m.coverage;
  std::string s = fmt::format(
      "{}: {}; coverage {:.4f} (n {:.4f}, k {})", m.material.name, m.material.source, c.both, c.n,
      std::isnan(c.k) ? std::string("not given") : fmt::format("{:.4f}", c.k));
  if (!c.extrapolated) return s + "; extrapolated: no";
  return s + "; extrapolated: yes, " + c.uncovered + " (the nearest measured value is held there)";
}

// How many of the materials hold a nearest value somewhere, and the lowest coverage.
std::string extrapolation_summary(const std::vector<analysis::MaterialStudy>& studies) {
  int held = 0;
  const analysis::LoadedMaterial* lowest = nullptr;
  for (const auto& s : studies) {
    held += s.material->coverage.extrapolated;
    if (!lowest || s.material->coverage.both < lowest->coverage.both) lowest = s.material;
  }
  std::string out = fmt::format("{} of {} materials are extrapolated", held, studies.size());
  if (lowest)
    out += fmt::format("; the lowest coverage is {:.4f} ({})", lowest->coverage.both,
                       lowest->material.name);
  return out + ".";
}

std::string document_comment(const analysis::Context& ctx, const MaterialxSpace& space,
                             MaterialxShader shader,
                             const std::vector<analysis::MaterialStudy>& studies) {
  const char* model = shader == MaterialxShader::GeneralizedSchlick
                          ? "generalized_schlick_bsdf with color0 = F0 and color82 = the F82 tint "
                            "(true F82 / Schlick at arccos(1/7)); "
                            "scatter_mode RT for clear dielectrics"
                      : shader == MaterialxShader::OpenPbrSurface
                          ? "open_pbr_surface: metals base_metalness 1, base_color = F0, "
                            "specular_color = the F82 tint; dielectrics "
                            "base_metalness 0, specular_ior = the index whose normal-incidence "
                            "reflectance is F0's luminance, "
                            "transmission_weight 1 when clear, base_weight 0 when opaque"
                          : "standard_surface: metals metalness 1, base_color = F0 (reflectivity), "
                            "specular_color = Gulbrandsen's edge "
                            "tint g; dielectrics metalness 0, specular_IOR as for OpenPBR, "
                            "transmission 1 when clear, base 0 when opaque";
  std::string c = fmt::format(
      "  <!-- Fresnel Lab presets as {}. Roughness and everything else keep the shading "
      "model's defaults. {}",
      model, analysis::setting_note(ctx));
  if (!space.note.empty()) c += " " + space.note + ".";
  c += fmt::format(
      " Each material's doc attribute states its data source; its coverage, the share of 360-830 "
      "nm (weighted by the illuminant × ȳ) that the data measures, for n and k together and each "
      "alone; whether it is extrapolated, the nearest measured value held where the data stops "
      "({}); and the colours below 0 or above 1 by more than {:g} (out_of_range), which are kept "
      "unclamped. {} -->\n",
      "a colour computed there is not measured", analysis::kOutOfRangeTolerance,
      extrapolation_summary(studies));
  return c;
}

}  // namespace

std::string presets_materialx(const analysis::Context& ctx,
                              const std::vector<analysis::MaterialStudy>& studies,
                              MaterialxShader shader) {
  const MaterialxSpace space = materialx_space(ctx);
  std::string out =
      "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" colorspace=\"" + space.name + "\">\n";
  out += document_comment(ctx, space, shader, studies);
  for (const auto& s : studies) {
    const auto p = analysis::shading_preset(ctx, s);
    const std::string id = node_id(s.material->material.key);
    Writer w{space, {}};
    out += shader_nodes(id, p, shader, w);
    const std::string flags = analysis::out_of_range_list(w.flags);
    std::string doc = provenance(*s.material);
    if (!flags.empty()) doc += "; out_of_range: " + flags;
    out += fmt::format(
        "  <surfacematerial name=\"{0}\" type=\"material\" doc=\"{1}\">\n"
        "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"{0}_shader\" />\n"
        "  </surfacematerial>\n",
        id, xml_attribute(doc));
  }
  return out + "</materialx>\n";
}

}  // namespace fl::report
