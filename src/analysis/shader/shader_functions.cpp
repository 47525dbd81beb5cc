// A model's shader functions: its punctual function (the unit's GLSL, or written from its table
// terms), its IBL and area functions (written from its table terms, or the model at n·v times the
// lobe's Fresnel-free integral) and their table lookups.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "analysis/shader/shader.h"
#include "analysis/shader/shader_parts.h"
#include "fresnel/registered_models.h"

namespace fl::analysis {
namespace shader_parts {

using fresnel::ModelSpec;

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

std::vector<const LutTexture*> sampled_textures(const ModelSpec& s, Lighting l) {
  const auto& support = l == Lighting::Ibl ? s.pre_integration.ibl : s.pre_integration.area;
  std::vector<const LutTexture*> out;
  for (const auto& t : lut_textures()) {
    if (t.lighting != std::string(lighting_name(l))) continue;
    bool used = false;
    for (const char* ch : support.channels)
      for (const auto& c : t.channels)
        used = used || (std::string(c.channel) == ch && std::string(c.components).size() == 1);
    if (used) out.push_back(&t);
  }
  return out;
}

// A texel of the texture as the table function takes it: vec4 when a channel lives in A, else
// vec3 (its swizzle "rgba" or "rgb").
bool texel_has_alpha(const LutTexture& t) {
  for (const auto& c : t.channels)
    if (std::string(c.components) == "a") return true;
  return false;
}

std::string sampler_name(const LutTexture& t, bool ibl) {
  return ibl ? std::string(t.name) + "_lut" : t.name;
}

std::string entry_signature(const ModelSpec& s, Lighting l, ShaderLanguage lang) {
  const bool ibl = l == Lighting::Ibl, glsl = lang == ShaderLanguage::Glsl;
  std::string samplers;
  for (const auto* t : sampled_textures(s, l))
    samplers +=
        fmt::format("{} {}, ", glsl ? "sampler2D" : "Texture2D<float4>", sampler_name(*t, ibl));
  return fmt::format("{} {}({}{}float nov, float perceptual_roughness, {})",
                     glsl ? "vec3" : "float3", shader_function_name(s.model, l), samplers,
                     glsl ? "" : "SamplerState lut_sampler, ",
                     translate(param_list(s, true), lang));
}

namespace {

// A float literal GLSL and HLSL read as float: nine significant digits, always with a point or
// an exponent.
std::string float_literal(double x) {
  std::string s = fmt::format("{:.9g}", x);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// float NAME(float mu): a table term (its registry entry's body, or its polynomial in
// x = 2μ − 1 by Horner's rule).
std::string term_function(const fresnel::TermSpec& t) {
  std::string body;
  if (t.glsl.body) {
    body = t.glsl.body;
  } else {
    body = "  float x = 2.0 * mu - 1.0;\n  float p = " +
           float_literal(t.glsl.polynomial[fresnel::kBasisPolyDegree]) + ";\n";
    for (int i = fresnel::kBasisPolyDegree; i-- > 0;)
      body += "  p = p * x + " + float_literal(t.glsl.polynomial[i]) + ";\n";
    body += "  return p;\n";
  }
  return fmt::format("// The table term {} at mu = v·h.\nfloat {}(float mu) {{\n{}}}\n", t.formula,
                     t.glsl.name, body);
}

// The weight of a term times what stands for the term, added to `sum`: " + w * x" (x alone for
// the term 1), or " - v * x" for a weight "-v" with no sum in v.
void add_weighted(std::string& sum, const fresnel::TermWeight& w, const std::string& term) {
  std::string weight = w.glsl;
  const bool minus = weight[0] == '-' && weight.find_first_of("+-", 1) == std::string::npos;
  if (minus)
    weight.erase(0, 1);
  else if (weight.find_first_of("+-") != std::string::npos)
    weight = "(" + weight + ")";
  sum += sum.empty() ? (minus ? "-" : "") : (minus ? " - " : " + ");
  sum += term.empty() ? weight : weight + " * " + term;
}

// The bodies written from a unit's table terms: at v·h (where the unit gives no body), from a DFG
// texel (the term's channel, plus the channel it is stored less of), from the LTC moments.
enum class BodyKind { Punctual, Dfg, Ltc };
std::string term_body(const ModelSpec& s, BodyKind kind) {
  std::string sum;
  for (const auto& w : s.term_weights) {
    const auto& t = fresnel::term_spec(w.term);
    std::string term;
    if (kind == BodyKind::Punctual)
      term = t.glsl.name ? fmt::format("{}(cos_theta)", t.glsl.name) : "";
    else if (kind == BodyKind::Ltc)
      term = t.ltc.channel;
    else if (t.dfg.less == t.term)
      term = t.dfg.channel;
    else
      term = fmt::format("({} + {})", t.dfg.channel, fresnel::term_spec(t.dfg.less).dfg.channel);
    add_weighted(sum, w, term);
  }
  return "  return " + sum + ";\n";
}

// The punctual body is generated when the unit gives none.
bool generated_punctual(const ModelSpec& s) {
  return std::string(s.shader.body).empty();
}
std::string punctual_body(const ModelSpec& s) {
  return generated_punctual(s) ? term_body(s, BodyKind::Punctual) : s.shader.body;
}

std::string punctual_function(const ModelSpec& s) {
  return fmt::format(
      "// {}, at cos_theta = v·h for a punctual light.\nvec3 fresnel_{}(float cos_theta, {}) "
      "{{\n{}}}\n",
      s.label, s.name, param_list(s, true), punctual_body(s));
}

// The lobe's Fresnel-free integral (the table term 1's) in the texel's channel names.
std::string lobe_integral(bool ibl) {
  const auto& one = fresnel::term_spec(fresnel::Term::One);
  if (!ibl) return one.ltc.channel;
  if (one.dfg.less == fresnel::Term::One) return one.dfg.channel;
  return fmt::format("({} + {})", one.dfg.channel, fresnel::term_spec(one.dfg.less).dfg.channel);
}

// A texture's texel in the table function (the first: dfg or moments) and its sampler (dfg_lut,
// dfg_2_lut; ltc_2, ltc_3).
std::string texel_name(const LutTexture& t, size_t k, bool ibl) {
  if (k == 0) return ibl ? "dfg" : "moments";
  return t.name;
}

// fresnel_NAME_dfg / _ltc: the texels' channels as named floats, then the unit's combination
// (pre-integrated) or the model at n·v times the lobe's Fresnel-free integral.
std::string table_function(const ModelSpec& s, Lighting l) {
  const bool ibl = l == Lighting::Ibl;
  const auto& support = ibl ? s.pre_integration.ibl : s.pre_integration.area;
  const auto textures = sampled_textures(s, l);
  std::string body, texels;
  for (const char* ch : support.channels) {
    const auto where = find_lut_channel(lighting_name(l), ch);
    if (std::string(where.components).size() != 1)
      continue;  // the LTC matrix: read by the polygon integral
    const size_t k = std::find(textures.begin(), textures.end(), where.texture) - textures.begin();
    body += fmt::format("  float {} = {}.{};\n", ch, texel_name(*where.texture, k, ibl),
                        where.components);
  }
  for (size_t k = 0; k < textures.size(); ++k)
    texels += fmt::format("{} {}, ", texel_has_alpha(*textures[k]) ? "vec4" : "vec3",
                          texel_name(*textures[k], k, ibl));
  if (!support.fresnel_pre_integrated)
    body += fmt::format("  return fresnel_{}(nov, {}) * {};\n", s.name, param_list(s, false),
                        lobe_integral(ibl));
  else
    body += term_body(s, ibl ? BodyKind::Dfg : BodyKind::Ltc);
  const std::string what =
      support.fresnel_pre_integrated
          ? "the Fresnel term pre-integrated in the table"
          : fmt::format("approximation: the model at {} times the lobe's Fresnel-free integral",
                        support.evaluated_at);
  return fmt::format("// {} from {} ({}).\nvec3 fresnel_{}_{}({}float nov, {}) {{\n{}}}\n", s.label,
                     textures.size() > 1 ? "a texel of each of its textures"
                     : ibl               ? "one DFG texel"
                                         : "one ltc_2 texel",
                     what, s.name, ibl ? "dfg" : "ltc", texels, param_list(s, true), body);
}

// The uv a lighting's lookup samples its textures at: both tables hold their axes' ends in their
// edge texels, so the axis position x maps to x·(N − 1)/N + ½/N for a table of N texels per axis:
// the DFG ones over (n·v, roughness), the LTC ones over (roughness, √(1 − n·v)).
std::string lookup_uv(Lighting l) {
  const bool ibl = l == Lighting::Ibl;
  return fmt::format(
      "{1} * (({0} - 1.0) / {0}) + 0.5 / {0}", ibl ? kDfgSizeMacro : kLtcSizeMacro,
      ibl ? "vec2(nov, perceptual_roughness)" : "vec2(perceptual_roughness, sqrt(1.0 - nov))");
}

// A table's size macro, defined unless the including code defined it.
std::string size_define(Lighting l, int lut_size) {
  const bool ibl = l == Lighting::Ibl;
  return fmt::format(
      "// The {2} tables' texels per axis (`fresnel-lab lut {3} --size {1}`); define {0} before "
      "this code for another size.\n#ifndef {0}\n#define {0} {1}.0\n#endif\n",
      ibl ? kDfgSizeMacro : kLtcSizeMacro, lut_size, ibl ? "DFG" : "LTC", ibl ? "dfg" : "ltc");
}

// The texture reads: GLSL sampler2D / HLSL Texture2D + SamplerState, at the table's uv convention.
std::string lookup_function(const ModelSpec& s, Lighting l, ShaderLanguage lang, int lut_size) {
  const bool ibl = l == Lighting::Ibl;
  const auto textures = sampled_textures(s, l);
  const std::string comment =
      size_define(l, lut_size) +
      (ibl ? "// Split sum: multiplies the prefiltered environment. dfg_lut: `fresnel-lab lut dfg "
             "--out dfg.exr`\n// (endpoints over n·v and perceptual roughness), bilinear, clamp to "
             "edge.\n"
           : "// Multiplies the LTC polygon integral (ltc_1: M⁻¹). ltc_2: `fresnel-lab lut ltc "
             "--out ltc.exr`\n// (endpoints over perceptual roughness and √(1 − n·v)), "
             "bilinear, clamp to edge.\n");
  const bool glsl = lang == ShaderLanguage::Glsl;
  std::string reads, texels;
  for (size_t k = 0; k < textures.size(); ++k) {
    const std::string tex = sampler_name(*textures[k], ibl),
                      texel = k ? fmt::format("texel_{}", k + 1) : "texel";
    const bool alpha = texel_has_alpha(*textures[k]);
    const std::string type = std::string(glsl ? "vec" : "float") + (alpha ? "4" : "3"),
                      uv = translate(lookup_uv(l), lang), swizzle = alpha ? "rgba" : "rgb";
    reads +=
        glsl ? fmt::format("  {} {} = textureLod({}, {}, 0.0).{};\n", type, texel, tex, uv, swizzle)
             : fmt::format("  {} {} = {}.SampleLevel(lut_sampler, {}, 0.0).{};\n", type, texel, tex,
                           uv, swizzle);
    texels += texel + ", ";
  }
  return fmt::format("{}{} {{\n{}  return fresnel_{}_{}({}nov, {});\n}}\n", comment,
                     entry_signature(s, l, lang), reads, s.name, ibl ? "dfg" : "ltc", texels,
                     param_list(s, false));
}

}  // namespace
}  // namespace shader_parts

using fresnel::Model;
using shader_parts::generated_punctual;
using shader_parts::lookup_function;
using shader_parts::punctual_function;
using shader_parts::table_function;
using shader_parts::term_function;
using shader_parts::translate;

std::string shader_code(Model m, const std::vector<Lighting>& lightings, ShaderLanguage lang,
                        int lut_size) {
  const auto& s = fresnel::model_spec(m);
  bool needs_model = false;
  for (Lighting l : lightings)
    needs_model =
        needs_model || l == Lighting::Punctual || !lighting_support(m, l).fresnel_pre_integrated;
  std::string glsl;
  std::set<std::string> emitted;
  for (const auto* h : s.shader.helpers)
    if (emitted.insert(h->name).second) glsl += (glsl.empty() ? "" : "\n") + std::string(h->source);
  for (const auto& w : s.term_weights) {
    const auto& t = fresnel::term_spec(w.term);
    if (needs_model && generated_punctual(s) && t.glsl.name && emitted.insert(t.glsl.name).second)
      glsl += "\n" + term_function(t);
  }
  if (needs_model) glsl += (glsl.empty() ? "" : "\n") + punctual_function(s);
  std::string out = translate(glsl, lang);
  for (Lighting l : lightings) {
    if (l == Lighting::Punctual) continue;
    out += (out.empty() ? "" : "\n") + translate(table_function(s, l), lang) + "\n" +
           lookup_function(s, l, lang, lut_size);
  }
  return out;
}

}  // namespace fl::analysis
