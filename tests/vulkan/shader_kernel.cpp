#include "vulkan/shader_kernel.h"

#include <fmt/format.h>

#include "analysis/lut/lut_layout.h"
#include "fresnel/registered_models.h"

namespace fl::test::vk {

using analysis::Lighting;
using analysis::ShaderLanguage;

size_t kernel_stride(fresnel::Model m) {
  const auto& s = fresnel::model_spec(m);
  return 2 + 3 * s.channel_params.size() + s.shared_params.size();
}

void append_inputs(std::vector<float>& inputs, fresnel::Model m, double x, double roughness,
                   const std::vector<double>& params) {
  inputs.push_back(static_cast<float>(x));
  inputs.push_back(static_cast<float>(roughness));
  const auto& s = fresnel::model_spec(m);
  const size_t channel = s.channel_params.size();
  // The flat layout (ModelSpec::param_names): channel c's parameter p at c·channel + p.
  for (size_t p = 0; p < channel; ++p)
    for (size_t c = 0; c < 3; ++c) inputs.push_back(static_cast<float>(params.at(c * channel + p)));
  for (size_t p = 0; p < s.shared_params.size(); ++p)
    inputs.push_back(static_cast<float>(params.at(3 * channel + p)));
}

namespace {

// The call's arguments after the angles: the parameters from the invocation's record.
std::string param_args(const fresnel::ModelSpec& s, bool glsl) {
  std::string out;
  size_t k = 2;
  for (size_t p = 0; p < s.channel_params.size(); ++p, k += 3)
    out += fmt::format(", {}(fl_in[b + {}], fl_in[b + {}], fl_in[b + {}])",
                       glsl ? "vec3" : "float3", k, k + 1, k + 2);
  for (size_t p = 0; p < s.shared_params.size(); ++p, ++k) out += fmt::format(", fl_in[b + {}]", k);
  return out;
}

}  // namespace

std::string kernel_source(fresnel::Model m, Lighting lighting, ShaderLanguage lang,
                          const std::string& include, size_t count) {
  const auto& s = fresnel::model_spec(m);
  const bool glsl = lang == ShaderLanguage::Glsl;
  const auto textures = analysis::shader_textures(m, lighting);
  std::string head, args;
  for (size_t t = 0; t < textures.size(); ++t) {
    head += glsl ? fmt::format("layout(binding = {}) uniform sampler2D fl_t{};\n", t + 2, t)
                 : fmt::format("[[vk::binding({})]] Texture2D<float4> fl_t{};\n", t + 2, t);
    args += fmt::format("fl_t{}, ", t);
  }
  if (!glsl && !textures.empty()) {
    head += fmt::format("[[vk::binding({})]] SamplerState fl_sampler;\n", textures.size() + 2);
    args += "fl_sampler, ";
  }
  args += lighting == Lighting::Punctual ? "fl_in[b]" : "fl_in[b], fl_in[b + 1]";
  const std::string call =
      analysis::shader_function_name(m, lighting) + "(" + args + param_args(s, glsl) + ")";
  const size_t stride = kernel_stride(m);
  if (glsl)
    return fmt::format(
        "#version 450 core\nlayout(local_size_x = 64) in;\n"
        "layout(std430, binding = 0) readonly buffer FlIn {{ float fl_in[]; }};\n"
        "layout(std430, binding = 1) writeonly buffer FlOut {{ vec4 fl_out[]; }};\n{}\n{}\n"
        "void main() {{\n  uint i = gl_GlobalInvocationID.x;\n  if (i >= {}u) return;\n"
        "  uint b = i * {}u;\n  fl_out[i] = vec4({}, 1.0);\n}}\n",
        head, include, count, stride, call);
  return fmt::format(
      "[[vk::binding(0)]] StructuredBuffer<float> fl_in;\n"
      "[[vk::binding(1)]] RWStructuredBuffer<float4> fl_out;\n{}\n{}\n"
      "[numthreads(64, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) {{\n  uint i = id.x;\n"
      "  if (i >= {}u) return;\n  uint b = i * {}u;\n  fl_out[i] = float4({}, 1.0);\n}}\n",
      head, include, count, stride, call);
}

std::vector<Texture> lighting_textures(fresnel::Model m, Lighting lighting,
                                       const std::string& folder) {
  std::vector<Texture> out;
  for (const auto& name : analysis::shader_textures(m, lighting))
    out.push_back(read_texture(folder + "/" + analysis::lut_texture_file(name)));
  return out;
}

std::vector<std::array<double, 3>> run_kernel(Device& device, fresnel::Model m, Lighting lighting,
                                              ShaderLanguage lang, const std::string& include,
                                              const std::vector<float>& inputs,
                                              const std::vector<Texture>& textures,
                                              Storage storage) {
  const size_t count = inputs.size() / kernel_stride(m);
  const bool hlsl = lang == ShaderLanguage::Hlsl;
  ComputeJob job;
  job.spirv = compile_compute(kernel_source(m, lighting, lang, include, count), hlsl,
                              analysis::shader_function_name(m, lighting));
  job.inputs = inputs;
  job.invocations = static_cast<std::uint32_t>(count);
  for (const auto& t : textures) job.textures.push_back(&t);
  job.storage = storage;
  job.separate_sampler = hlsl;
  const auto out = device.run(job);
  std::vector<std::array<double, 3>> rgb(count);
  for (size_t k = 0; k < count; ++k)
    for (int c = 0; c < 3; ++c) rgb[k][c] = out[4 * k + c];
  return rgb;
}

}  // namespace fl::test::vk
