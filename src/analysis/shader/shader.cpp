#include "analysis/shader/shader.h"

#include <fmt/format.h>

#include <cctype>
#include <set>

#include "analysis/lut/lut_layout.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"

namespace fl::analysis {

using fresnel::Model;
using fresnel::ModelSpec;

ShaderLanguage shader_language_from_name(const std::string& name) {
  if (name == "glsl") return ShaderLanguage::Glsl;
  if (name == "hlsl") return ShaderLanguage::Hlsl;
  throw InputError(fmt::format("unknown shader language '{}' (expected glsl or hlsl)", name));
}

std::string shader_function_name(Model m, Lighting l) {
  const std::string base = std::string("fresnel_") + fresnel::model_spec(m).name;
  return l == Lighting::Punctual ? base : base + "_" + lighting_name(l);
}

namespace {

// GLSL → HLSL for the subset the units keep to: whole identifiers renamed.
std::string translate(const std::string& glsl, ShaderLanguage lang) {
  if (lang == ShaderLanguage::Glsl) return glsl;
  static const std::vector<std::pair<std::string, std::string>> kRenames{
      {"vec2", "float2"}, {"vec3", "float3"},       {"vec4", "float4"},
      {"mix", "lerp"},    {"inversesqrt", "rsqrt"}, {"fract", "frac"}};
  std::string out;
  for (size_t i = 0; i < glsl.size();) {
    if (!std::isalpha(static_cast<unsigned char>(glsl[i])) && glsl[i] != '_') {
      out += glsl[i++];
      continue;
    }
    size_t j = i;
    while (j < glsl.size() && (std::isalnum(static_cast<unsigned char>(glsl[j])) || glsl[j] == '_'))
      ++j;
    std::string word = glsl.substr(i, j - i);
    for (const auto& [from, to] : kRenames)
      if (word == from) word = to;
    out += word;
    i = j;
  }
  return out;
}

// "vec3 f0, vec3 f82" (typed) or "f0, f82" (a call's arguments).
std::string param_list(const ModelSpec& s, bool typed) {
  std::string out;
  auto add = [&](const char* type, const char* name) {
    out +=
        fmt::format("{}{}{}", out.empty() ? "" : ", ", typed ? std::string(type) + " " : "", name);
  };
  for (const auto& p : s.channel_params) add("vec3", p.name);
  for (const auto& p : s.shared_params) add("float", p.name);
  return out;
}

std::string punctual_function(const ModelSpec& s) {
  return fmt::format(
      "// {}, at cos_theta = v·h for a punctual light.\nvec3 fresnel_{}(float cos_theta, {}) "
      "{{\n{}}}\n",
      s.label, s.name, param_list(s, true), s.shader.body);
}

// The lobe's Fresnel-free integral (the table term 1's) in the texel's channel names.
std::string lobe_integral(bool ibl) {
  const auto& one = fresnel::term_spec(fresnel::Term::One);
  if (!ibl) return one.ltc_channel;
  if (one.dfg_less == fresnel::Term::One) return one.dfg_channel;
  return fmt::format("({} + {})", one.dfg_channel, fresnel::term_spec(one.dfg_less).dfg_channel);
}

// fresnel_NAME_dfg / _ltc: the texel's channels as named floats, then the unit's combination
// (pre-integrated) or the model at n·v times the lobe's Fresnel-free integral.
std::string table_function(const ModelSpec& s, Lighting l) {
  const bool ibl = l == Lighting::Ibl;
  const auto& support = ibl ? s.pre_integration.ibl : s.pre_integration.area;
  const std::string texel = ibl ? "dfg" : "moments";
  std::string body;
  for (const char* ch : support.channels) {
    const auto where = find_lut_channel(lighting_name(l), ch);
    if (std::string(where.components).size() != 1)
      continue;  // the LTC matrix: read by the polygon integral
    body += fmt::format("  float {} = {}.{};\n", ch, texel, where.components);
  }
  if (support.fresnel_pre_integrated) {
    body += ibl ? s.shader.dfg_body : s.shader.ltc_body;
  } else {
    body += fmt::format("  return fresnel_{}(nov, {}) * {};\n", s.name, param_list(s, false),
                        lobe_integral(ibl));
  }
  const std::string what =
      support.fresnel_pre_integrated
          ? "the Fresnel term pre-integrated in the table"
          : fmt::format("approximation: the model at {} times the lobe's Fresnel-free integral",
                        support.evaluated_at);
  return fmt::format(
      "// {} from one {} texel ({}).\nvec3 fresnel_{}_{}(vec3 {}, float nov, {}) {{\n{}}}\n",
      s.label, ibl ? "DFG" : "ltc_2", what, s.name, ibl ? "dfg" : "ltc", texel, param_list(s, true),
      body);
}

// The texture read: GLSL sampler2D / HLSL Texture2D + SamplerState, at the table's uv convention.
std::string lookup_function(const ModelSpec& s, Lighting l, ShaderLanguage lang) {
  const bool ibl = l == Lighting::Ibl;
  const char* tex = ibl ? "dfg_lut" : "ltc_2";
  const std::string uv =
      ibl ? "vec2(nov, perceptual_roughness)"
          : fmt::format(
                "vec2(perceptual_roughness, sqrt(1.0 - nov)) * ({0}.0 / {1}.0) + 0.5 / {1}.0",
                kEngineLutSize - 1, kEngineLutSize);
  const std::string comment = ibl ? "// Split sum: multiplies the prefiltered environment. "
                                    "dfg_lut: `fresnel-lab lut dfg --out dfg.exr`\n"
                                    "// (texel centres over n·v and perceptual roughness: no uv "
                                    "remapping), bilinear, clamp to edge.\n"
                                  : fmt::format(
                                        "// Multiplies the LTC polygon integral (ltc_1: M⁻¹). "
                                        "ltc_2: `fresnel-lab lut ltc --size {}`\n"
                                        "// (endpoints over perceptual roughness and √(1 − n·v)), "
                                        "bilinear, clamp to edge.\n",
                                        kEngineLutSize);
  const std::string args = param_list(s, false);
  if (lang == ShaderLanguage::Glsl)
    return fmt::format(
        "{}vec3 {}(sampler2D {}, float nov, float perceptual_roughness, {}) {{\n"
        "  vec3 texel = textureLod({}, {}, 0.0).rgb;\n  return fresnel_{}_{}(texel, nov, "
        "{});\n}}\n",
        comment, shader_function_name(s.model, l), tex, param_list(s, true), tex, uv, s.name,
        ibl ? "dfg" : "ltc", args);
  return fmt::format(
      "{}float3 {}(Texture2D<float4> {}, SamplerState lut_sampler, float nov, float "
      "perceptual_roughness, "
      "{}) {{\n  float3 texel = {}.SampleLevel(lut_sampler, {}, 0.0).rgb;\n"
      "  return fresnel_{}_{}(texel, nov, {});\n}}\n",
      comment, shader_function_name(s.model, l), tex, translate(param_list(s, true), lang), tex,
      translate(uv, lang), s.name, ibl ? "dfg" : "ltc", args);
}

}  // namespace

std::string shader_code(Model m, const std::vector<Lighting>& lightings, ShaderLanguage lang) {
  const auto& s = fresnel::model_spec(m);
  bool needs_model = false;
  for (Lighting l : lightings)
    needs_model =
        needs_model || l == Lighting::Punctual || !lighting_support(m, l).fresnel_pre_integrated;
  std::string glsl =
      fmt::format("// Generated by fresnel-lab: {} ({}).\n", s.label, param_list(s, true));
  std::set<std::string> emitted;
  for (const auto* h : s.shader.helpers)
    if (emitted.insert(h->name).second) glsl += "\n" + std::string(h->source);
  if (needs_model) glsl += "\n" + punctual_function(s);
  std::string out = translate(glsl, lang);
  for (Lighting l : lightings) {
    if (l == Lighting::Punctual) continue;
    out += "\n" + translate(table_function(s, l), lang) + "\n" + lookup_function(s, l, lang);
  }
  return out;
}

std::string shader_text(const ShaderRequest& r) {
  const auto lang = shader_language_from_name(r.lang);
  const auto lighting = lighting_from_name(r.lighting);
  const auto model = fresnel::model_from_name(r.model).model;
  if (r.harness && lang != ShaderLanguage::Glsl) throw InputError("--harness writes GLSL only");
  return r.harness ? shader_cost_harness(model, lighting) : shader_code(model, {lighting}, lang);
}

std::string shader_cost_harness(Model m, Lighting l) {
  const auto& s = fresnel::model_spec(m);
  std::string members = "  float cos_theta;\n  float perceptual_roughness;\n";
  std::string args =
      l == Lighting::Punctual ? "u.cos_theta" : "lut, u.cos_theta, u.perceptual_roughness";
  for (const auto& p : s.channel_params) {
    members += fmt::format("  vec3 {};\n", p.name);
    args += fmt::format(", u.{}", p.name);
  }
  for (const auto& p : s.shared_params) {
    members += fmt::format("  float {};\n", p.name);
    args += fmt::format(", u.{}", p.name);
  }
  return fmt::format(
      "#version 450\nlayout(local_size_x = 1) in;\nlayout(std140, binding = 0) uniform Inputs "
      "{{\n{}}} u;\n"
      "layout(std430, binding = 1) buffer Outputs {{ vec3 rgb; }} o;\n{}\n{}\n"
      "void main() {{ o.rgb = {}({}); }}\n",
      members, l == Lighting::Punctual ? "" : "layout(binding = 2) uniform sampler2D lut;\n",
      shader_code(m, {l}, ShaderLanguage::Glsl), shader_function_name(m, l), args);
}

}  // namespace fl::analysis
