#include "report/materialx.h"

#include <fmt/format.h>

#include <cctype>

#include "analysis/tables/tables.h"

namespace fl::report {

std::string presets_materialx(const analysis::Context& ctx, const std::vector<analysis::MaterialStudy>& studies) {
  // MaterialX's names for our working spaces (its colour-management vocabulary).
  const std::string& space = ctx.settings().space;
  const std::string mtlx_space = space == "aces2065-1"   ? "lin_ap0"
                                 : space == "lin_p3d65"  ? "lin_displayp3"
                                 : space == "lin_rec2020" ? "lin_rec2020"
                                                          : space;
  std::string out = "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\" colorspace=\"" + mtlx_space + "\">\n";
  out += fmt::format("  <!-- Fresnel Lab presets: generalized_schlick_bsdf with color0 = F0 and color82 = the F82 tint "
                     "(true F82 / Schlick at arccos(1/7)); {} -->\n", analysis::setting_note(ctx));
  for (const auto& s : studies) {
    std::string id = s.material->material.key;
    for (auto& ch : id)
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "m_" + id;
    const auto& d = s.derived;
    auto c3 = [](const color::Rgb& v) { return fmt::format("{:.6f}, {:.6f}, {:.6f}", v.r, v.g, v.b); };
    out += fmt::format("  <generalized_schlick_bsdf name=\"{0}_bsdf\" type=\"BSDF\">\n"
                       "    <input name=\"color0\" type=\"color3\" value=\"{1}\" />\n"
                       "    <input name=\"color82\" type=\"color3\" value=\"{2}\" />\n"
                       "    <input name=\"color90\" type=\"color3\" value=\"1, 1, 1\" />\n"
                       "  </generalized_schlick_bsdf>\n"
                       "  <surface name=\"{0}_surface\" type=\"surfaceshader\">\n"
                       "    <input name=\"bsdf\" type=\"BSDF\" nodename=\"{0}_bsdf\" />\n"
                       "  </surface>\n"
                       "  <surfacematerial name=\"{0}\" type=\"material\">\n"
                       "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"{0}_surface\" />\n"
                       "  </surfacematerial>\n",
                       id, c3(d.f0), c3(d.f82_tint));
  }
  return out + "</materialx>\n";
}

}  // namespace fl::report
