#pragma once
// Where the files `lut` writes keep each lookup-table channel (fresnel::lut_channel): one place for
// the plan's table list and the shaders' lookups (jobs/lut_files.cpp writes these layouts).
#include <string>
#include <vector>

namespace fl::analysis {

struct LutChannelLocation {
  const char* channel;  // fresnel::lut_channel name
  const char*
      components;  // texture components holding it: "r", "g", "b", "a", or "rgba" (the LTC matrix)
};
struct LutTexture {
  const char* name;      // dfg | ltc_1 | ltc_2
  const char* lighting;  // ibl | area
  const char* file;      // what `command` writes
  const char* command;
  std::vector<LutChannelLocation> channels;
};

// The DFG texture: `lut dfg` (Filament's convention: texel centres over (n·v, perceptual
// roughness), sampled at uv = (n·v, roughness) with no remapping). The LTC textures: `lut ltc`
// (Heitz's convention: endpoints over (roughness, √(1 − n·v)); shaders sample
// uv = (roughness, √(1 − n·v))·(N − 1)/N + ½/N).
const std::vector<LutTexture>& lut_textures();
// The texture holding a channel, and its components there.
struct LutLookup {
  const LutTexture* texture = nullptr;
  const char* components = "";
};
LutLookup find_lut_channel(const std::string& lighting, const std::string& channel);

}  // namespace fl::analysis
