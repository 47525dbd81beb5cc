#include "analysis/shader/shader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "analysis/lut/lut_layout.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::analysis {

using fresnel::Model;
using fresnel::ModelSpec;

ShaderLanguage shader_language_from_name(const std::string& name) {
  const std::vector<NameChoice> choices = {{"glsl", {}}, {"hlsl", {}}};
  const auto match = match_name(name, choices);
  if (!match) throw InputError(unknown_name_message("shader language", name, choices));
  return *match == "glsl" ? ShaderLanguage::Glsl : ShaderLanguage::Hlsl;
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
  if (t.glsl_body) {
    body = t.glsl_body;
  } else {
    body = "  float x = 2.0 * mu - 1.0;\n  float p = " +
           float_literal(t.polynomial[fresnel::kBasisPolyDegree]) + ";\n";
    for (int i = fresnel::kBasisPolyDegree; i-- > 0;)
      body += "  p = p * x + " + float_literal(t.polynomial[i]) + ";\n";
    body += "  return p;\n";
  }
  return fmt::format("// The table term {} at mu = v·h.\nfloat {}(float mu) {{\n{}}}\n", t.formula,
                     t.glsl_name, body);
}

// The weight of a term times what stands for the term: "w * x", or x alone for the term 1.
std::string weighted(const fresnel::TermWeight& w, const std::string& term) {
  std::string weight = w.glsl;
  if (weight.find_first_of("+-") != std::string::npos) weight = "(" + weight + ")";
  return term.empty() ? weight : weight + " * " + term;
}

// The bodies a unit with term weights leaves to the emitter: at v·h, from a DFG texel (the term's
// channel, plus the channel it is stored less of), from the LTC moments.
enum class BodyKind { Punctual, Dfg, Ltc };
std::string term_body(const ModelSpec& s, BodyKind kind) {
  std::string sum;
  for (const auto& w : s.shader.term_weights) {
    const auto& t = fresnel::term_spec(w.term);
    std::string term;
    if (kind == BodyKind::Punctual)
      term = t.glsl_name ? fmt::format("{}(cos_theta)", t.glsl_name) : "";
    else if (kind == BodyKind::Ltc)
      term = t.ltc_channel;
    else if (t.dfg_less == t.term)
      term = t.dfg_channel;
    else
      term = fmt::format("({} + {})", t.dfg_channel, fresnel::term_spec(t.dfg_less).dfg_channel);
    sum += (sum.empty() ? "" : " + ") + weighted(w, term);
  }
  return "  return " + sum + ";\n";
}

std::string punctual_body(const ModelSpec& s) {
  return s.shader.term_weights.empty() ? s.shader.body : term_body(s, BodyKind::Punctual);
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
  if (!ibl) return one.ltc_channel;
  if (one.dfg_less == fresnel::Term::One) return one.dfg_channel;
  return fmt::format("({} + {})", one.dfg_channel, fresnel::term_spec(one.dfg_less).dfg_channel);
}

// The textures a lighting's entry point samples: those holding its single-component channels (the
// LTC matrix is read by the polygon integral), in lut_textures() order.
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

// A texture's texel in the table function (the first: dfg or moments) and its sampler (dfg_lut,
// dfg_2_lut; ltc_2, ltc_3).
std::string texel_name(const LutTexture& t, size_t k, bool ibl) {
  if (k == 0) return ibl ? "dfg" : "moments";
  return t.name;
}
std::string sampler_name(const LutTexture& t, bool ibl) {
  return ibl ? std::string(t.name) + "_lut" : t.name;
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
    texels += fmt::format("vec3 {}, ", texel_name(*textures[k], k, ibl));
  if (!support.fresnel_pre_integrated)
    body += fmt::format("  return fresnel_{}(nov, {}) * {};\n", s.name, param_list(s, false),
                        lobe_integral(ibl));
  else if (!s.shader.term_weights.empty())
    body += term_body(s, ibl ? BodyKind::Dfg : BodyKind::Ltc);
  else
    body += ibl ? s.shader.dfg_body : s.shader.ltc_body;
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

// vec3 fresnel_NAME_ibl(sampler2D dfg_lut, ..., float nov, float perceptual_roughness, vec3 f0,
// ...) (HLSL: the textures, then SamplerState lut_sampler).
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
    reads += fmt::format(fmt::runtime(glsl ? "  vec3 {} = textureLod({}, {}, 0.0).rgb;\n"
                                           : "  float3 {} = {}.SampleLevel(lut_sampler, {}, "
                                             "0.0).rgb;\n"),
                         texel, tex, translate(lookup_uv(l), lang));
    texels += texel + ", ";
  }
  return fmt::format("{}{} {{\n{}  return fresnel_{}_{}({}nov, {});\n}}\n", comment,
                     entry_signature(s, l, lang), reads, s.name, ibl ? "dfg" : "ltc", texels,
                     param_list(s, false));
}

// "R dfg1, G dfg2, B dfg_f82": a texture's channels at their components.
std::string texture_channels(const LutTexture& t) {
  std::string out;
  for (const auto& c : t.channels) {
    std::string comp = c.components;
    for (char& ch : comp) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", comp, c.channel);
  }
  return out;
}

// The command writing a texture's table at `size`: its lut_textures() command with --size.
std::string sized_command(const LutTexture& t, int size) {
  std::string cmd = t.command;
  const auto at = cmd.find(" --out");
  return cmd.insert(at, fmt::format(" --size {}", size));
}

// One comment line per lighting (what to call) and per table the lookups sample.
std::string lighting_lines(const ModelSpec& s, const std::vector<Lighting>& ls,
                           const ShaderDocument& d) {
  std::string out;
  for (Lighting l : ls) {
    if (l == Lighting::Punctual) {
      out += fmt::format("// Lighting punctual: {} fresnel_{}(float cos_theta, {}), at v.h.\n",
                         d.lang == ShaderLanguage::Glsl ? "vec3" : "float3", s.name,
                         translate(param_list(s, true), d.lang));
      continue;
    }
    const bool pre = lighting_support(s.model, l).fresnel_pre_integrated;
    out +=
        fmt::format("// Lighting {}: {} ({}).\n", lighting_name(l), entry_signature(s, l, d.lang),
                    pre ? "the Fresnel term pre-integrated in the tables"
                        : "the model at n.v times the lobe's Fresnel-free integral");
    for (const auto* t : sampled_textures(s, l))
      out += fmt::format("// Table {} ({}), {}x{} texels: `{}` writes {}.\n", t->name,
                         texture_channels(*t), d.lut_size, d.lut_size,
                         sized_command(*t, d.lut_size), t->file);
    if (l == Lighting::Area)
      out += fmt::format(
          "// Table ltc_1 (the LTC matrix), {0}x{0}: read by the engine's polygon integral, not "
          "here; {1} = {0}.0 maps uv to the LTC tables' texel centres.\n",
          d.lut_size, kLtcSizeMacro);
  }
  return out;
}

// What the document is and what it was checked with.
std::string checked_lines(const ShaderDocument& d) {
  const bool glsl = d.lang == ShaderLanguage::Glsl;
  std::string what = d.standalone
                         ? fmt::format(
                               "// A complete {} fragment shader: the include and an entry "
                               "point for checking it (inputs from the uniform block "
                               "FresnelLabInputs, the lightings' sum as the colour).\n",
                               glsl ? "GLSL" : "HLSL")
                     : glsl ? "// A GLSL include: no #version line; put it after your shader's "
                              "`#version 450 core` (or later) line.\n"
                            : "// An HLSL include: functions only, no entry point.\n";
  return what +
         (glsl ? "// Checked with: GLSL `#version 450 core`, fragment stage (glslangValidator -V "
                 "-S frag, then spirv-val), as `--standalone` prints it.\n"
               : "// Checked with: HLSL pixel shader, Shader Model 5 syntax (Texture2D, "
                 "SamplerState, SampleLevel), glslangValidator's HLSL front end (-D -V -S frag -e "
                 "main, then spirv-val), as `--standalone` prints it.\n");
}

std::string document_comment(const ModelSpec& s, const std::vector<Lighting>& ls,
                             const ShaderDocument& d) {
  std::string out = fmt::format("// Generated by `{}`.\n", d.command);
  out += fmt::format(
      "// Model {} ({}): parameters {}, {}.\n", s.name, s.label,
      translate(param_list(s, true), d.lang),
      d.standalone ? "from the uniform block FresnelLabInputs" : "the functions' arguments");
  out += lighting_lines(s, ls, d);
  for (const auto& n : d.notes) out += "// " + n + "\n";
  return out + checked_lines(d);
}

// The inputs of the standalone entry point: the angles the lightings take, then the parameters.
std::vector<std::pair<std::string, std::string>> entry_inputs(const ModelSpec& s,
                                                              const std::vector<Lighting>& ls) {
  std::vector<std::pair<std::string, std::string>> in;
  const bool punctual = std::find(ls.begin(), ls.end(), Lighting::Punctual) != ls.end();
  if (punctual) in.emplace_back("float", "cos_theta");
  if (ls.size() > (punctual ? 1u : 0u)) {
    in.emplace_back("float", "nov");
    in.emplace_back("float", "perceptual_roughness");
  }
  for (const auto& p : s.channel_params) in.emplace_back("vec3", p.name);
  for (const auto& p : s.shared_params) in.emplace_back("float", p.name);
  return in;
}

// The call of a lighting's function in the standalone entry point, its inputs named by `input`.
std::string entry_call(const ModelSpec& s, Lighting l, ShaderLanguage lang,
                       const std::string& input) {
  std::string args = l == Lighting::Punctual ? input + "cos_theta" : "";
  if (l != Lighting::Punctual) {
    for (const auto* t : sampled_textures(s, l))
      args += "fl_" + sampler_name(*t, l == Lighting::Ibl) + ", ";
    if (lang == ShaderLanguage::Hlsl) args += "fl_lut_sampler, ";
    args += input + "nov, " + input + "perceptual_roughness";
  }
  for (const auto& p : s.channel_params) args += ", " + input + p.name;
  for (const auto& p : s.shared_params) args += ", " + input + p.name;
  return fmt::format("  rgb += {}({});\n", shader_function_name(s.model, l), args);
}

// The standalone entry point: the uniform block, the tables (bindings 1, 2, ...), main.
std::string entry_point(const ModelSpec& s, const std::vector<Lighting>& ls, ShaderLanguage lang) {
  const bool glsl = lang == ShaderLanguage::Glsl;
  std::string out = glsl
                        ? "\n// Entry point for checking the include.\nlayout(std140, binding = 0) "
                          "uniform FresnelLabInputs {\n"
                        : "\n// Entry point for checking the include.\ncbuffer FresnelLabInputs : "
                          "register(b0) {\n";
  for (const auto& [type, name] : entry_inputs(s, ls))
    out += fmt::format("  {} {}{};\n", translate(type, lang), glsl ? "" : "fl_", name);
  out += glsl ? "} fl_in;\n" : "};\n";
  int binding = 1;
  std::string calls;
  for (Lighting l : ls) {
    for (const auto* t :
         l == Lighting::Punctual ? std::vector<const LutTexture*>{} : sampled_textures(s, l))
      out += fmt::format(fmt::runtime(glsl ? "layout(binding = {0}) uniform sampler2D fl_{1};\n"
                                           : "Texture2D<float4> fl_{1} : register(t{0});\n"),
                         binding++, sampler_name(*t, l == Lighting::Ibl));
    calls += entry_call(s, l, lang, glsl ? "fl_in." : "fl_");
  }
  if (glsl)
    return out +
           "layout(location = 0) out vec4 fl_colour;\n\nvoid main() {\n  vec3 rgb = "
           "vec3(0.0);\n" +
           calls + "  fl_colour = vec4(rgb, 1.0);\n}\n";
  return out +
         "SamplerState fl_lut_sampler : register(s0);\n\nfloat4 main() : SV_Target {\n  "
         "float3 rgb = float3(0.0, 0.0, 0.0);\n" +
         calls + "  return float4(rgb, 1.0);\n}\n";
}

}  // namespace

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
  for (const auto& w : s.shader.term_weights) {
    const auto& t = fresnel::term_spec(w.term);
    if (needs_model && t.glsl_name && emitted.insert(t.glsl_name).second)
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

std::string shader_document(Model m, const std::vector<Lighting>& lightings,
                            const ShaderDocument& d) {
  const auto& s = fresnel::model_spec(m);
  const std::string code =
      document_comment(s, lightings, d) + "\n" + shader_code(m, lightings, d.lang, d.lut_size);
  if (!d.standalone) return code;
  return (d.lang == ShaderLanguage::Glsl ? "#version 450 core\n" : "") + code +
         entry_point(s, lightings, d.lang);
}

void check_lut_size(int size) {
  if (size < 2 || size > 4096)
    throw InputError(fmt::format("--size {} out of range (2 to 4096)", size));
}

std::string shader_text(const ShaderRequest& r) {
  const auto lang = shader_language_from_name(r.lang);
  const auto lighting = lighting_from_name(r.lighting);
  const auto model = fresnel::model_from_name(r.model).model;
  if (r.harness && lang != ShaderLanguage::Glsl) throw InputError("--harness writes GLSL only");
  if (r.harness && r.standalone) throw InputError("--harness and --standalone exclude each other");
  check_lut_size(r.size);
  if (r.harness) return shader_cost_harness(model, lighting);
  ShaderDocument d{lang, r.size, r.standalone, {}, {}};
  d.command =
      fmt::format("fresnel-lab shader {} --lang {} --lighting {} --size {}{}",
                  fresnel::model_spec(model).name, lang == ShaderLanguage::Glsl ? "glsl" : "hlsl",
                  lighting_name(lighting), r.size, r.standalone ? " --standalone" : "");
  return shader_document(model, {lighting}, d);
}

std::vector<std::string> shader_textures(Model m, Lighting l) {
  std::vector<std::string> out;
  if (l == Lighting::Punctual) return out;
  for (const auto* t : sampled_textures(fresnel::model_spec(m), l)) out.push_back(t->name);
  return out;
}

std::string shader_cost_harness(Model m, Lighting l) {
  const auto& s = fresnel::model_spec(m);
  std::string members = "  float cos_theta;\n  float perceptual_roughness;\n";
  std::string samplers, args = l == Lighting::Punctual ? "u.cos_theta" : "";
  const auto textures = shader_textures(m, l);
  for (size_t k = 0; k < textures.size(); ++k) {
    const std::string name = k ? fmt::format("lut_{}", k + 1) : "lut";
    samplers += fmt::format("layout(binding = {}) uniform sampler2D {};\n", k + 2, name);
    args += name + ", ";
  }
  if (l != Lighting::Punctual) args += "u.cos_theta, u.perceptual_roughness";
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
      members, samplers, shader_code(m, {l}, ShaderLanguage::Glsl), shader_function_name(m, l),
      args);
}

}  // namespace fl::analysis
