#pragma once
// Shader code for a Fresnel model: the model's own function (from its unit's GLSL,
// fresnel/model_spec.h ShaderCode) and, for pre-integrated lighting, the lookup of the tables in
// the layout `lut` writes (analysis/lut/lut_layout.h), in GLSL or HLSL.
//
// Functions, per model NAME, with its per-channel parameters as vec3 and shared ones as float:
//   punctual  vec3 fresnel_NAME(float cos_theta, ...)      the model at a light's v·h
//   ibl       vec3 fresnel_NAME_dfg(vec3 dfg, [vec4 dfg_2,] float nov, ...) from a DFG texel
//             (r, g, b) and, for a model using the basis terms, a dfg_2 texel (r, g, b, a)
//             vec3 fresnel_NAME_ibl(DFG texture(s), float nov, float perceptual_roughness, ...)
//                 the split-sum factor that multiplies the prefiltered environment
//   area      vec3 fresnel_NAME_ltc(vec3 moments, [vec4 ltc_3,] float nov, ...) from an ltc_2
//             texel (r, g, b) and, for the basis terms, an ltc_3 texel (r, g, b, a)
//             vec3 fresnel_NAME_area(ltc_2 [, ltc_3] texture, float nov, float
//             perceptual_roughness, ...) the Fresnel-weighted norm that multiplies the LTC
//             polygon integral
// The textures an entry point samples are those holding the channels its model declares
// (shader_textures), in the order of analysis::lut_textures().
#include <string>
#include <vector>

#include "analysis/lut/rendered.h"
#include "fresnel/model_spec.h"

namespace fl::analysis {

enum class ShaderLanguage { Glsl, Hlsl };
ShaderLanguage shader_language_from_name(
    const std::string& name);  // glsl | hlsl; InputError otherwise

// The name of the function an engine calls for model m under lighting l.
std::string shader_function_name(fresnel::Model m, Lighting l);

// The macros holding the DFG and LTC tables' sizes (texels per axis, a float) that the IBL and area
// lookups map their uv with (both tables hold their axes' ends in their edge texels:
// uv = x·(N − 1)/N + ½/N); shader_code defines each from `lut_size` unless the including code
// defined it first.
inline constexpr const char* kDfgSizeMacro = "FRESNEL_LAB_DFG_SIZE";
inline constexpr const char* kLtcSizeMacro = "FRESNEL_LAB_LTC_SIZE";

// Self-contained code for model m under each of `lightings`: the helpers it calls (once), the
// model's function where a lighting evaluates it, and each lighting's entry point; under area
// lights, for LTC tables of lut_size² texels.
std::string shader_code(fresnel::Model m, const std::vector<Lighting>& lightings,
                        ShaderLanguage lang, int lut_size = kEngineLutSize);

// What a shader document says about itself and what it holds.
struct ShaderDocument {
  ShaderLanguage lang = ShaderLanguage::Glsl;
  int lut_size = kEngineLutSize;   // the tables' size (`lut --size`)
  bool standalone = false;         // a complete fragment shader instead of an include
  std::string command;             // the command that printed it, for the first line
  std::vector<std::string> notes;  // further comment lines (a plan: each material's parameters)
};
// An include: a comment naming its command, model, lightings and entry points, the tables it
// samples with their size and the commands writing them, and the language and profile it is
// checked with (no #version line), then shader_code. Standalone: #version 450 core (GLSL), the
// include, and a fragment entry point (GLSL main writing a colour output, HLSL main returning
// SV_Target) calling each lighting's function with inputs from a uniform block.
std::string shader_document(fresnel::Model m, const std::vector<Lighting>& lightings,
                            const ShaderDocument& doc);
// InputError unless 2 ≤ size ≤ 4096 (the sizes `lut` writes).
void check_lut_size(int size);

// The textures fresnel_NAME_ibl / _area samples, in argument order (none for punctual lights).
std::vector<std::string> shader_textures(fresnel::Model m, Lighting l);

// A GLSL compute shader around shader_code(m, {l}) for measuring its cost: the entry point's
// inputs come from a uniform block, its result goes to a storage buffer, so an optimizer can
// neither fold nor drop the function (scripts/gpu_costs.sh compiles it).
std::string shader_cost_harness(fresnel::Model m, Lighting l);

// `shader MODEL --lang L --lighting L [--size N] [--standalone | --harness]`: the names and size
// checked (InputError), then shader_document or shader_cost_harness (GLSL only).
struct ShaderRequest {
  std::string model, lang = "glsl", lighting = "punctual";
  bool harness = false;
  int size = kEngineLutSize;
  bool standalone = false;
};
std::string shader_text(const ShaderRequest& request);

}  // namespace fl::analysis
