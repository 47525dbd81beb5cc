#include "analysis/lut/lut_layout.h"

#include <stdexcept>

#include "fresnel/model_spec.h"

namespace fl::analysis {

namespace {

// Each table term's channel and component in the DFG or the ltc_2 texture.
std::vector<LutChannelLocation> term_channels(bool dfg) {
  std::vector<LutChannelLocation> out;
  for (const auto& t : fresnel::kTermRegistry)
    out.push_back(dfg ? LutChannelLocation{t.dfg_channel, t.dfg_component}
                      : LutChannelLocation{t.ltc_channel, t.ltc_component});
  return out;
}

}  // namespace

const std::vector<LutTexture>& lut_textures() {
  static const std::vector<LutTexture> textures{
      {"dfg", "ibl", "dfg.exr", "fresnel-lab lut dfg --out dfg.exr", term_channels(true)},
      {"ltc_1",
       "area",
       "ltc_1.exr",
       "fresnel-lab lut ltc --out ltc.exr",
       {{fresnel::lut_channel::kLtcMatrix, "rgba"}}},
      {"ltc_2", "area", "ltc_2.exr", "fresnel-lab lut ltc --out ltc.exr", term_channels(false)},
  };
  return textures;
}

LutLookup find_lut_channel(const std::string& lighting, const std::string& channel) {
  for (const auto& t : lut_textures())
    for (const auto& c : t.channels)
      if (lighting == t.lighting && channel == c.channel) return {&t, c.components};
  throw std::logic_error("no lookup table holds channel " + channel + " under " + lighting);
}

}  // namespace fl::analysis
