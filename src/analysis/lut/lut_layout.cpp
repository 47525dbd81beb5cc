#include "analysis/lut/lut_layout.h"

#include <stdexcept>
#include <string>

#include "fresnel/model_spec.h"

namespace fl::analysis {

namespace {

// The texture names the table terms live in, in registry order: dfg, dfg_2, ... or ltc_2, ltc_3.
std::vector<const char*> term_textures(bool dfg) {
  std::vector<const char*> out;
  for (const auto& t : fresnel::kTermRegistry) {
    const char* name = dfg ? t.dfg.texture : t.ltc.texture;
    bool seen = false;
    for (const char* n : out) seen = seen || std::string(n) == name;
    if (!seen) out.push_back(name);
  }
  return out;
}

// The table terms' channels and components in one DFG or LTC texture.
std::vector<LutChannelLocation> term_channels(bool dfg, const std::string& texture) {
  std::vector<LutChannelLocation> out;
  for (const auto& t : fresnel::kTermRegistry)
    if (texture == (dfg ? t.dfg.texture : t.ltc.texture))
      out.push_back(dfg ? LutChannelLocation{t.dfg.channel, t.dfg.component}
                        : LutChannelLocation{t.ltc.channel, t.ltc.component});
  return out;
}

std::vector<LutTexture> make_textures() {
  std::vector<LutTexture> out;
  for (const char* name : term_textures(true))
    out.push_back({name, "ibl", lut_texture_file(name), "fresnel-lab lut dfg --out dfg.exr",
                   term_channels(true, name)});
  out.push_back({"ltc_1",
                 "area",
                 "ltc_1.exr",
                 "fresnel-lab lut ltc --out ltc.exr",
                 {{fresnel::lut_channel::kLtcMatrix, "rgba"}}});
  for (const char* name : term_textures(false))
    out.push_back({name, "area", lut_texture_file(name), "fresnel-lab lut ltc --out ltc.exr",
                   term_channels(false, name)});
  return out;
}

}  // namespace

const char* lut_texture_file(const std::string& texture) {
  static const std::vector<std::string> files = [] {
    std::vector<std::string> f;
    for (bool dfg : {true, false})
      for (const char* n : term_textures(dfg)) f.push_back(std::string(n) + ".exr");
    return f;
  }();
  for (const auto& f : files)
    if (f == texture + ".exr") return f.c_str();
  throw std::logic_error("no lookup table texture " + texture);
}

std::vector<std::string> term_texture_names(bool dfg) {
  const auto names = term_textures(dfg);
  return {names.begin(), names.end()};
}

const std::vector<LutTexture>& lut_textures() {
  static const std::vector<LutTexture> textures = make_textures();
  return textures;
}

LutLookup find_lut_channel(const std::string& lighting, const std::string& channel) {
  for (const auto& t : lut_textures())
    for (const auto& c : t.channels)
      if (lighting == t.lighting && channel == c.channel) return {&t, c.components};
  throw std::logic_error("no lookup table holds channel " + channel + " under " + lighting);
}

}  // namespace fl::analysis
