#pragma once
// A headless Vulkan compute runner for the shader tests: one device (the first the loader lists),
// storage buffers in and out, and lookup-table textures uploaded as an engine uploads them
// (RGBA16F or RGBA32F, optimal tiling, linear filtering, clamp to edge, one mip level).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fl::test::vk {

// Texel storage of an uploaded table.
enum class Storage { Half, Float };
const char* storage_name(Storage s);  // half | float

// An RGBA float texture; texel (x, y) is rgba[4·(y·width + x) + c], row y = 0 at texture v = 0.
struct Texture {
  int width = 0, height = 0;
  std::vector<float> rgba;
};
// An EXR file's R, G, B and A channels (A = 1 where absent) as a texture, rows in file order.
Texture read_texture(const std::string& exr_path);

// A compute dispatch. Bindings (set 0): 0 the input floats (storage buffer), 1 the output vec4s
// (storage buffer), then the textures from 2: combined image samplers (GLSL), or sampled images
// followed by one sampler at 2 + textures.size() (HLSL's Texture2D and SamplerState).
struct ComputeJob {
  std::vector<std::uint32_t> spirv;
  std::vector<float> inputs;
  std::uint32_t invocations = 0;  // one output vec4 each; local size 64
  std::vector<const Texture*> textures;
  Storage storage = Storage::Float;
  bool separate_sampler = false;
};

class Device {
 public:
  // Throws std::runtime_error when no Vulkan device is found or one cannot be set up.
  Device();
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  std::string name() const;    // the device's name (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)")
  std::string driver() const;  // "driver NAME, Vulkan a.b.c"
  // Runs the job and returns invocations × 4 floats.
  std::vector<float> run(const ComputeJob& job);

  struct State;  // the Vulkan objects (vk_compute.cpp)

 private:
  std::unique_ptr<State> s_;
};

// The test binary's one device, made on first use (throws as Device() does).
Device& shared_device();

// GLSL (or, with hlsl, HLSL through glslang's HLSL front end, entry point main) compute source to
// SPIR-V with glslangValidator (-V, --target-env vulkan1.1); throws std::runtime_error with the
// compiler's messages when it fails.
std::vector<std::uint32_t> compile_compute(const std::string& source, bool hlsl,
                                           const std::string& name);

}  // namespace fl::test::vk
