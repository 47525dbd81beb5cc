#include "analysis/lut/lut_layout.h"

#include <stdexcept>

#include "fresnel/model.h"

namespace fl::analysis {

const std::vector<LutTexture>& lut_textures() {
  namespace ch = fresnel::lut_channel;
  static const std::vector<LutTexture> textures{
      {"dfg",
       "ibl",
       "dfg.exr",
       "fresnel-lab lut dfg --out dfg.exr",
       {{ch::kDfgScale, "r"}, {ch::kDfgBias, "g"}, {ch::kDfgF82, "b"}}},
      {"ltc_1",
       "area",
       "ltc_1.exr",
       "fresnel-lab lut ltc --out ltc.exr",
       {{ch::kLtcMatrix, "rgba"}}},
      {"ltc_2",
       "area",
       "ltc_2.exr",
       "fresnel-lab lut ltc --out ltc.exr",
       {{ch::kLtcNorm, "r"}, {ch::kLtcSchlick, "g"}, {ch::kLtcF82, "b"}}},
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
