#include "documents/materialx.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "analysis/presets/shading_presets.h"
#include "analysis/study/table_notes.h"
#include "documents/html.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::documents {

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
  const analysis::Context& ctx;
  const MaterialxSpace& space;
  analysis::NamedValues flags;  // the colours of the current material, by MaterialX input name
  std::string stored;           // what was stored in [0, 1] instead (the out-of-range policy)

  std::string color(const std::string& input, const color::Rgb& working) {
    color::Rgb v = color::transform_rgb(space.from_working, working);
    analysis::add_channels(flags, input, v);
    analysis::NamedValues own;
    analysis::add_channels(own, input, v);
    if (!analysis::out_of_range_list(own).empty()) {
      const color::Mat3 to_working = space.from_working.inverse();
      const auto unit = analysis::into_unit_range(ctx, v, &to_working);
      stored += fmt::format(
          "; {} ({:.4f}, {:.4f}, {:.4f}) stored as ({:.4f}, {:.4f}, {:.4f}), "
          "ΔE2000 {:.2f}",
          input, v.r, v.g, v.b, unit.value.r, unit.value.g, unit.value.b, unit.de00);
      v = unit.value;
    }
    return fmt::format(
        "    <input name=\"{}\" type=\"color3\" value=\"{:.6f}, {:.6f}, {:.6f}\" />\n", input, v.r,
        v.g, v.b);
  }
  static std::string number(const std::string& input, double v) {
    return fmt::format("    <input name=\"{}\" type=\"float\" value=\"{:.6g}\" />\n", input, v);
  }
};

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
                         MaterialxShader shader, double roughness, Writer& w) {
  std::string s;
  if (shader == MaterialxShader::GeneralizedSchlick) {
    s = fmt::format("  <generalized_schlick_bsdf name=\"{}_bsdf\" type=\"BSDF\">\n", id);
    s += w.color("color0", p.f0);
    s += w.color("color82", p.f82_tint);
    s += "    <input name=\"color90\" type=\"color3\" value=\"1, 1, 1\" />\n";
    const double alpha = roughness * roughness;  // the BSDF's roughness is α
    s += fmt::format("    <input name=\"roughness\" type=\"vector2\" value=\"{:.6g}, {:.6g}\" />\n",
                     alpha, alpha);
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
  s += w.number("specular_roughness", roughness);
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

std::string rgb_range(const color::Rgb& lo, const color::Rgb& hi) {
  return fmt::format("r {:.4f}-{:.4f}, g {:.4f}-{:.4f}, b {:.4f}-{:.4f}", lo.r, hi.r, lo.g, hi.g,
                     lo.b, hi.b);
}

// A consensus material's basis: its pages, their spread and each channel's range.
std::string consensus_basis(const analysis::ConsensusBasis& b) {
  if (b.pages == 1) return "; a single bulk page, not a consensus: its spread is unknown";
  return fmt::format(
      "; consensus of {} bulk pages: ΔE2000 from it F0 median {:.2f}, max {:.2f}, F82 median "
      "{:.2f}, max {:.2f}; F0 of the pages (working space) {}; F82 {}",
      b.pages, b.f0_median, b.f0_max, b.f82_median, b.f82_max, rgb_range(b.f0_lo, b.f0_hi),
      rgb_range(b.f82_lo, b.f82_hi));
}

// What a material's data is and how much of the visible range it measures, for its doc attribute.
std::string provenance(const analysis::LoadedMaterial& m) {
  const auto& c = m.coverage;
  std::string s = fmt::format(
      "{}: {}; coverage {:.4f} (n {:.4f}, k {})", m.material.name, m.material.source, c.both, c.n,
      std::isnan(c.k) ? std::string("not given") : fmt::format("{:.4f}", c.k));
  if (m.consensus) s += consensus_basis(*m.consensus);
  if (!m.resolved.empty()) s += "; resolved: " + m.resolved;
  if (!c.extrapolated) return s + "; extrapolated: no";
  return s + "; extrapolated: yes, " + c.uncovered + " (the nearest measured value is held there)";
}

// Why an opaque dielectric is written as a metal.
std::string representation_note(const analysis::ShadingPreset& p) {
  if (!p.metal_form) return {};
  return fmt::format(
      "; written as a metal: a dielectric of one index misses its F0 or F82 by {:.2f} ΔE2000 "
      "(limit {:g})",
      p.dielectric_form_de00, analysis::kDielectricFormMaxDe00);
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
                             const std::vector<analysis::MaterialStudy>& studies,
                             const analysis::ExportOptions& options) {
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
      "  <!-- Fresnel Lab presets as {}. Opaque dielectrics that one index does not reproduce "
      "are written as metals. Perceptual roughness {:g} (alpha {:g}); every other input keeps the "
      "shading model's default. {}",
      model, options.roughness, options.roughness * options.roughness, analysis::setting_note(ctx));
  if (!space.note.empty()) c += " " + space.note + ".";
  c += fmt::format(
      " Each material's doc attribute states its data source; its coverage, the share of 360-830 "
      "nm (weighted by the illuminant × ȳ) that the data measures, for n and k together and each "
      "alone; whether it is extrapolated, the nearest measured value held where the data stops "
      "({}); a consensus' pages and spread; and the colours below 0 or above 1 by more than {:g} "
      "(out_of_range), which are stored as the colour of [0, 1]^3 nearest in ΔE2000, the true "
      "value and its cost beside. {}",
      "a colour computed there is not measured", analysis::kOutOfRangeTolerance,
      extrapolation_summary(studies));
  if (!options.skipped.empty()) {
    c += fmt::format(" Skipped {} material{}:", options.skipped.size(),
                     options.skipped.size() == 1 ? "" : "s");
    for (const auto& s : options.skipped) c += " " + s + ";";
  }
  return c + " -->\n";
}

}  // namespace

std::string presets_materialx(const analysis::Context& ctx,
                              const std::vector<analysis::MaterialStudy>& studies,
                              MaterialxShader shader, const analysis::ExportOptions& options) {
  const MaterialxSpace space = materialx_space(ctx);
  std::string out =
      "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" colorspace=\"" + space.name + "\">\n";
  out += document_comment(ctx, space, shader, studies, options);
  for (const auto& s : studies) {
    const auto p = analysis::shading_preset(ctx, s);
    const std::string id = node_id(s.material->material.key);
    Writer w{ctx, space, {}, {}};
    out += shader_nodes(id, p, shader, options.roughness, w);
    const std::string flags = analysis::out_of_range_list(w.flags);
    std::string doc = provenance(*s.material) + representation_note(p);
    if (!flags.empty()) doc += "; out_of_range: " + flags + w.stored;
    out += fmt::format(
        "  <surfacematerial name=\"{0}\" type=\"material\" doc=\"{1}\">\n"
        "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"{0}_shader\" />\n"
        "  </surfacematerial>\n",
        id, html_escape(doc));
  }
  return out + "</materialx>\n";
}

}  // namespace fl::documents
