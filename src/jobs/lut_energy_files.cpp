// `lut energy`: the Kulla–Conty tables' files.
#include <fmt/format.h>

#include "analysis/lut/energy.h"
#include "documents/table_formats.h"
#include "jobs/lut_files.h"
#include "jobs/lut_texture.h"

namespace fl::jobs {

using namespace lut_files;

// ----- energy

namespace {

std::string energy_axes(const analysis::LutGrid& g) {
  return fmt::format(
      "x = n.v, y = perceptual roughness, {}; rows from smooth to rough (the first row is texture "
      "v = 0, GL order)",
      g.convention);
}
constexpr const char* kEnergyChannels =
    "R = E = integral rho cos (the GGX lobe's directional albedo, height-correlated Smith, no "
    "Fresnel), G = E_avg = 2 integral_0^1 E(mu) mu dmu (the same for every texel of a row)";
std::string energy_shader(const analysis::LutGrid& g) {
  return fmt::format(
      "vec2 e = textureLod(energyLut, {}, 0.0).rg; Kulla-Conty: f_ms = (1 - E(NoV)) (1 - E(NoL)) "
      "/ (pi (1 - e.g)) * F_avg^2 e.g / (1 - F_avg (1 - e.g))",
      dfg_uv_text(g));
}

std::string energy_csv(const analysis::EnergyTable& t) {
  const auto& g = t.grid;
  Table tab;
  tab.name = "energy";
  tab.columns = {col("nov"), col("perceptual_roughness"), col("alpha"), col("e"), col("e_avg")};
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i)
      tab.rows.push_back(
          {g.nov[i], g.perceptual_roughness[j], g.alpha[j], t.e[g.index(i, j)], t.e_avg[j]});
  return fmt::format("# axes: {}\n# channels: {}\n# shader: {}\n", energy_axes(g), kEnergyChannels,
                     energy_shader(g)) +
         documents::to_csv(tab);
}

io::ExrImage energy_texture(const analysis::EnergyTable& t) {
  const auto& g = t.grid;
  const Axes axes = dfg_axes(g);
  auto img = texture("energy", g.size, {"R", "G"}, axes, g.convention, kEnergyChannels);
  img.string_attributes.emplace_back("fresnelLab:shader", energy_shader(g));
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i)
      img.pixels.insert(img.pixels.end(),
                        {static_cast<float>(t.e[g.index(i, j)]), static_cast<float>(t.e_avg[j])});
  return img;
}

}  // namespace

io::Output energy_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  if (request.dielectric) return dielectric_energy_lut(request, progress);
  const LutRequest r = sized(request, kDefaultSize);
  const std::string ext = io::output_extension(r.out, {".exr", ".csv", ".h"});
  const std::string symbol = header_symbol(r, ext, "fresnel_lab_energy");
  const auto t = analysis::energy_table(analysis::dfg_grid(r.size), lut_options(r, progress));
  std::string bytes = ext == ".csv"
                          ? energy_csv(t)
                          : texture_bytes(energy_texture(t), ext,
                                          {symbol, lut_command("energy", r, symbol)}, r.half);
  return one_file("lut energy", r.out, std::move(bytes));
}
}  // namespace fl::jobs
