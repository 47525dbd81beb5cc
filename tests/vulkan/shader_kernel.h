#pragma once
// A compute kernel around a shipped shader include (`fresnel-lab shader`, `plan --out`): one
// invocation per shading point, its inputs read from a float buffer, the entry point's RGB written
// to a vec4 buffer (tests/vulkan/vk_compute.h's bindings).
#include <string>
#include <vector>

#include "analysis/shader/shader.h"
#include "vulkan/vk_compute.h"

namespace fl::test::vk {

// The driver against the CPU model reading the texels in the same storage (analysis::EngineTables),
// absolute in linear RGB: the driver's single-precision arithmetic and filtering (8-bit bilinear
// weights, as some GPUs filter, would exceed these); half tables also the conversion of the
// filtered half texels.
inline constexpr double kFloatTolerance = 2e-4;
inline constexpr double kHalfTolerance = 1e-3;
// ΔE2000 of the driver's output against the truth, against the CPU model's per point.
inline constexpr double kDe00Tolerance = 0.005;

// Per invocation, kernel_inputs' record: cos θ (punctual) or n·v, then perceptual roughness, then
// the model's parameters in its order (each channel parameter as r, g, b; then the shared ones).
size_t kernel_stride(fresnel::Model m);
void append_inputs(std::vector<float>& inputs, fresnel::Model m, double x, double roughness,
                   const std::vector<double>& params);

// The include followed by main() calling the model's function for `lighting`, with the
// textures shader_textures(m, lighting) bound from 2 in that order (HLSL: their sampler after
// them), for `count` invocations.
std::string kernel_source(fresnel::Model m, analysis::Lighting lighting,
                          analysis::ShaderLanguage lang, const std::string& include, size_t count);

// The textures the function for `lighting` samples, read from `folder` (their `lut` file names).
std::vector<Texture> lighting_textures(fresnel::Model m, analysis::Lighting lighting,
                                       const std::string& folder);

// Compiles kernel_source and runs it on `device`: RGB per invocation.
std::vector<std::array<double, 3>> run_kernel(
    Device& device, fresnel::Model m, analysis::Lighting lighting, analysis::ShaderLanguage lang,
    const std::string& include, const std::vector<float>& inputs,
    const std::vector<Texture>& textures, Storage storage);

}  // namespace fl::test::vk
