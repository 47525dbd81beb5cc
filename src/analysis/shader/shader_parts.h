#pragma once
// The parts of a model's shader code the emitter (shader.cpp) assembles documents from: the
// model's functions, written from its unit's GLSL and its table terms (the term registry,
// fresnel/table_terms.h), and the lookups of the tables in the layout `lut` writes.
#include <string>
#include <vector>

#include "analysis/lut/lut_layout.h"
#include "analysis/shader/shader.h"
#include "fresnel/model_spec.h"

namespace fl::analysis::shader_parts {

// GLSL → HLSL for the subset the units keep to: whole identifiers renamed.
std::string translate(const std::string& glsl, ShaderLanguage lang);
// "vec3 f0, vec3 f82" (typed) or "f0, f82" (a call's arguments).
std::string param_list(const fresnel::ModelSpec& s, bool typed);
// The textures a lighting's entry point samples: those holding its single-component channels (the
// LTC matrix is read by the polygon integral), in lut_textures() order.
std::vector<const LutTexture*> sampled_textures(const fresnel::ModelSpec& s, Lighting l);
// A texture's sampler: dfg_lut, dfg_2_lut; ltc_2, ltc_3.
std::string sampler_name(const LutTexture& t, bool ibl);
// vec3 fresnel_NAME_ibl(sampler2D dfg_lut, ..., float nov, float perceptual_roughness, vec3 f0,
// ...) (HLSL: the textures, then SamplerState lut_sampler).
std::string entry_signature(const fresnel::ModelSpec& s, Lighting l, ShaderLanguage lang);

}  // namespace fl::analysis::shader_parts
