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
  const char* name;      // dfg, dfg_2, ... | ltc_1 | ltc_2, ltc_3, ...
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
// The textures holding the table terms (fresnel::kTermRegistry), in registry order: the DFG
// textures (dfg, dfg_2, ...) or the LTC ones beside the matrix (ltc_2, ltc_3, ...).
std::vector<std::string> term_texture_names(bool dfg);
// The file a texture is written to by the command that writes its table: NAME.exr.
const char* lut_texture_file(const std::string& texture);
// The texture holding a channel, and its components there.
struct LutLookup {
  const LutTexture* texture = nullptr;
  const char* components = "";
};
LutLookup find_lut_channel(const std::string& lighting, const std::string& channel);

}  // namespace fl::analysis
