// `lut energy --dielectric`: the dielectric specular lobe's directional and average albedo with the
// exact Fresnel reflectance (analysis/lut/energy.h) as a square atlas of η-slices (EXR or C
// header) or CSV.
#include <fmt/format.h>

#include <cmath>

#include "analysis/lut/energy.h"
#include "documents/table_formats.h"
#include "jobs/lut_files.h"
#include "jobs/lut_texture.h"
#include "util/errors.h"

namespace fl::jobs {
namespace {

using namespace lut_files;

// Tiles per side of the atlas of `slices` slices (a square number from 4 to 64); InputError else.
int atlas_tiles(int slices) {
  for (int t = 2; t <= 8; ++t)
    if (t * t == slices) return t;
  throw InputError(fmt::format(
      "--slices {} must be a square number from 4 to 64 (the slices tile a square atlas)", slices));
}

std::string dielectric_axes(const analysis::DielectricEnergyTable& t, int tiles) {
  const int n = t.grid.size;
  return fmt::format(
      "a square atlas of {0}x{0} tiles of {1}x{1} texels; slice k in tile (k mod {0}, k div {0}), "
      "texel (x, y) = (({2}) * {1} + i, ({3}) * {1} + j); within a tile x = n.v, y = perceptual "
      "roughness, {4} (within a tile; the atlas uv is the shader's); rows from smooth to rough "
      "(the first row is texture v = 0, GL order); slice "
      "k holds F0 = {5:g} (k/{6})^4 (uniform in t = (F0/{5:g})^(1/4)), eta = (1 + sqrt(F0))/(1 - "
      "sqrt(F0)) (1 to {7:g})",
      tiles, n, "k mod " + std::to_string(tiles), "k div " + std::to_string(tiles),
      t.grid.convention, analysis::kDielectricMaxF0, t.slices.size() - 1,
      analysis::eta_from_f0(analysis::kDielectricMaxF0));
}

constexpr const char* kDielectricChannels =
    "the GGX specular lobe (height-correlated Smith) weighted by the exact unpolarized dielectric "
    "Fresnel reflectance F(v.h, eta), reflection only: R = E_F(mu, eta) = integral F rho cos, G = "
    "E_F,avg(eta) = 2 integral_0^1 E_F(mu) mu dmu (the same along a row; at roughness 0 it is "
    "F_avg(eta)), B and A the same at 1/eta (inside the medium looking out: same F0, total "
    "internal reflection past the critical angle)";

std::string dielectric_shader(const analysis::DielectricEnergyTable& t, int tiles) {
  const int n = t.grid.size, k = static_cast<int>(t.slices.size());
  return fmt::format(
      "float t = sqrt(abs(eta - 1.0) / ((eta + 1.0) * {0:g})); float s = clamp(t, 0.0, 1.0) * "
      "{1}.0; int k = min(int(s), {2}); vec2 st = vec2(NoV, perceptualRoughness) * {3}.0 + 0.5; "
      "vec2 uv0 = (vec2(k % {4}, k / {4}) * {5}.0 + st) / {6}.0, uv1 = (vec2((k + 1) % {4}, (k + "
      "1) "
      "/ {4}) * {5}.0 + st) / {6}.0; vec4 e = mix(textureLod(lut, uv0, 0.0), textureLod(lut, uv1, "
      "0.0), s - float(k)); eta >= 1: E_F = e.r, E_F,avg = e.g; eta < 1: E_F = e.b, E_F,avg = e.a. "
      "Layering: base *= (1 - E_F(NoV)) (1 - E_F(NoL)) / (1 - E_F,avg)",
      std::sqrt(analysis::kDielectricMaxF0), k - 1, k - 2, n - 1, tiles, n, tiles * n);
}

std::string slice_list(const analysis::DielectricEnergyTable& t) {
  std::string s;
  for (size_t k = 0; k < t.slices.size(); ++k)
    s += fmt::format("{}{}: F0 = {:.6g}, eta = {:.9g}", k ? "; " : "", k, t.slices[k].f0,
                     t.slices[k].eta);
  return s;
}

io::ExrImage dielectric_texture(const analysis::DielectricEnergyTable& t, int tiles) {
  const auto& g = t.grid;
  const int n = g.size, side = tiles * n;
  auto img = texture("energy-dielectric", side, {"R", "G", "B", "A"}, dfg_axes(g),
                     dielectric_axes(t, tiles), kDielectricChannels);
  img.string_attributes.emplace_back("fresnelLab:slices", slice_list(t));
  img.string_attributes.emplace_back("fresnelLab:shader", dielectric_shader(t, tiles));
  img.pixels.reserve(static_cast<size_t>(side) * side * 4);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const auto& s = t.slices[static_cast<size_t>((y / n) * tiles + x / n)];
      const int i = x % n, j = y % n, c = g.index(i, j);
      img.pixels.insert(img.pixels.end(),
                        {static_cast<float>(s.e_out[c]), static_cast<float>(s.e_avg_out[j]),
                         static_cast<float>(s.e_in[c]), static_cast<float>(s.e_avg_in[j])});
    }
  return img;
}

std::string dielectric_csv(const analysis::DielectricEnergyTable& t, int tiles) {
  const auto& g = t.grid;
  Table tab;
  tab.name = "energy-dielectric";
  tab.columns = {
      {"slice", 0}, col("f0"), col("eta"),   col("nov"),      col("perceptual_roughness"),
      col("alpha"), col("e"),  col("e_avg"), col("e_inside"), col("e_avg_inside")};
  for (size_t k = 0; k < t.slices.size(); ++k) {
    const auto& s = t.slices[k];
    for (int j = 0; j < g.size; ++j)
      for (int i = 0; i < g.size; ++i) {
        const int c = g.index(i, j);
        tab.rows.push_back({static_cast<long long>(k), s.f0, s.eta, g.nov[i],
                            g.perceptual_roughness[j], g.alpha[j], s.e_out[c], s.e_avg_out[j],
                            s.e_in[c], s.e_avg_in[j]});
      }
  }
  return fmt::format(
             "# axes: {}\n# channels: e = E_F(eta), e_avg = E_F,avg(eta), e_inside and "
             "e_avg_inside the same at 1/eta; {}\n# shader: {}\n",
             dielectric_axes(t, tiles), kDielectricChannels, dielectric_shader(t, tiles)) +
         documents::to_csv(tab);
}

}  // namespace

io::Output dielectric_energy_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const LutRequest r = sized(request, kDefaultSize);
  const int tiles = atlas_tiles(r.slices);
  const std::string ext = io::output_extension(r.out, {".exr", ".csv", ".h"});
  const std::string symbol = header_symbol(r, ext, "fresnel_lab_energy_dielectric");
  const auto t = analysis::dielectric_energy_table(analysis::dfg_grid(r.size), r.slices,
                                                   lut_options(r, progress));
  std::string bytes = ext == ".csv"
                          ? dielectric_csv(t, tiles)
                          : texture_bytes(dielectric_texture(t, tiles), ext,
                                          {symbol, lut_command("energy", r, symbol)}, r.half);
  return one_file("lut energy --dielectric", r.out, std::move(bytes));
}

}  // namespace fl::jobs
