#pragma once
// Shader code for a Fresnel model: the model's own function (from its unit's GLSL,
// fresnel/model_spec.h ShaderCode) and, for pre-integrated lighting, the lookup of the tables in
// the layout `lut` writes (analysis/lut/lut_layout.h), in GLSL or HLSL.
//
// Functions, per model NAME, with its per-channel parameters as vec3 and shared ones as float:
//   punctual  vec3 fresnel_NAME(float cos_theta, ...)      the model at a light's v·h
//   ibl       vec3 fresnel_NAME_dfg(vec3 dfg, float nov, ...) from a DFG texel (r, g, b)
//             vec3 fresnel_NAME_ibl(DFG texture, float nov, float perceptual_roughness, ...)
//                 the split-sum factor that multiplies the prefiltered environment
//   area      vec3 fresnel_NAME_ltc(vec3 moments, float nov, ...) from an ltc_2 texel (r, g, b)
//             vec3 fresnel_NAME_area(ltc_2 texture, float nov, float perceptual_roughness, ...)
//                 the Fresnel-weighted norm that multiplies the LTC polygon integral
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

// Self-contained code for model m under each of `lightings`: the helpers it calls (once), the
// model's function where a lighting evaluates it, and each lighting's entry point.
std::string shader_code(fresnel::Model m, const std::vector<Lighting>& lightings,
                        ShaderLanguage lang);

// A GLSL compute shader around shader_code(m, {l}) for measuring its cost: the entry point's
// inputs come from a uniform block, its result goes to a storage buffer, so an optimizer can
// neither fold nor drop the function (scripts/gpu_costs.sh compiles it).
std::string shader_cost_harness(fresnel::Model m, Lighting l);

// `shader MODEL --lang L --lighting L [--harness]`: the names checked (InputError), then
// shader_code or shader_cost_harness (GLSL only).
struct ShaderRequest {
  std::string model, lang = "glsl", lighting = "punctual";
  bool harness = false;
};
std::string shader_text(const ShaderRequest& request);

}  // namespace fl::analysis
