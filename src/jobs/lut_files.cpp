#include "jobs/lut_files.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "analysis/ltc/ltc_table.h"
#include "analysis/lut/energy.h"
#include "documents/table_formats.h"
#include "io/exr.h"
#include "util/errors.h"

namespace fl::report {
namespace {

constexpr int kDefaultSize = 64;

// The request with its size (default_size when 0), checked.
LutRequest sized(LutRequest r, int default_size) {
  if (r.size == 0) r.size = default_size;
  if (r.size < 2 || r.size > 4096)
    throw InputError(fmt::format("--size {} out of range (2 to 4096)", r.size));
  if (r.samples < 1) throw InputError(fmt::format("--samples {} must be positive", r.samples));
  if (r.threads < 0)
    throw InputError(fmt::format("--threads {} must be 0 (all) or positive", r.threads));
  return r;
}

analysis::LutOptions lut_options(const LutRequest& r, const analysis::LutProgress& progress) {
  return {r.samples, r.threads, progress};
}

// Nine significant digits: every value a float holds, small ones included.
analysis::Column col(const char* name) {
  return {name, 9, true, true};
}

// Texture-axis attributes shared by every EXR written here.
struct Axes {
  std::string x_axis;
  double x_min, x_max;
  std::string y_axis;
  double y_min, y_max;
};
constexpr const char* kRoughnessAxis = "perceptual_roughness";

ExrImage texture(const std::string& table, int size, std::vector<std::string> channels,
                 const Axes& a, const std::string& grid, const std::string& channel_text) {
  ExrImage img;
  img.width = img.height = size;
  img.channels = std::move(channels);
  img.string_attributes = {{"fresnelLab:table", table},
                           {"fresnelLab:xAxis", a.x_axis},
                           {"fresnelLab:yAxis", a.y_axis},
                           {"fresnelLab:grid", grid},
                           {"fresnelLab:channels", channel_text},
                           {"fresnelLab:rowOrder", "row y = 0 is the first y-axis value"}};
  img.float_attributes = {{"fresnelLab:xMin", static_cast<float>(a.x_min)},
                          {"fresnelLab:xMax", static_cast<float>(a.x_max)},
                          {"fresnelLab:yMin", static_cast<float>(a.y_min)},
                          {"fresnelLab:yMax", static_cast<float>(a.y_max)}};
  return img;
}

// The LTC texture layout (Heitz & Hill's ltc_code packTab): x = roughness (j), y = √(1 − n·v) (i).
const Axes kLtcAxes{kRoughnessAxis, 0.0, 1.0, "sqrt(1 - nov)", 0.0, 1.0};

Output one_file(const std::string& what, const std::string& path, std::string bytes) {
  Output o;
  o.files.emplace_back(path, std::move(bytes));
  o.messages.push_back(fmt::format("{}: wrote {}", what, path));
  return o;
}

// ----- dfg

// What a DFG file says about itself: its axes, channels and the shader code that reads it.
struct DfgText {
  std::string axes, channels, shader;
};
DfgText dfg_text(DfgLayout layout, const analysis::LutGrid& g) {
  const std::string axes = fmt::format(
      "x = n.v, y = perceptual roughness (alpha = roughness^2), {}; rows from smooth "
      "to rough (the first row is texture v = 0, GL order)",
      g.convention);
  if (layout == DfgLayout::SplitSum)
    return {axes,
            "R = dfg1 = integral (1 - Fc) rho cos, G = dfg2 = integral Fc rho cos, B = dfg_f82 = "
            "integral mu (1 - mu)^6 rho "
            "cos, with Fc = (1 - mu)^5, mu = v.h, rho cos the GGX lobe with height-correlated "
            "Smith masking",
            "vec3 dfg = textureLod(dfgLut, vec2(NoV, perceptualRoughness), 0.0).rgb; Schlick: E = "
            "f0 * dfg.r + dfg.g; "
            "Hoffman's F82 model: E = f0 * dfg.r + dfg.g - a * dfg.b, a = (823543/46656) (f0 - "
            "f82) + (49/6) (1 - f0)"};
  return {axes,
          "Filament's multiscatter DFG: R = integral Fc rho cos, G = integral rho cos, B = "
          "integral D_charlie V_neubelt "
          "cos (the sheen albedo, Estevez & Kulla 2017 NDF, Neubelt & Pettineo 2013 visibility), "
          "Fc = (1 - v.h)^5",
          "Filament: dfg = textureLod(light_iblDFG, vec2(NoV, perceptualRoughness), 0.0).rgb; "
          "specularDFG = "
          "mix(dfg.xxx, dfg.yyy, f0); energyCompensation = 1.0 + f0 * (1.0 / dfg.y - 1.0); "
          "sheenDFG = dfg.z"};
}

std::vector<std::string> dfg_channel_names(DfgLayout layout) {
  if (layout == DfgLayout::SplitSum) {
    std::vector<std::string> names;
    for (const auto& t : fresnel::kTermRegistry) names.push_back(t.dfg_channel);
    return names;
  }
  return {"dfg_fc", "dfg_norm", "dfg_sheen"};
}

// Three values per texel in file order (roughness-major, like the cells).
std::vector<double> dfg_values(DfgLayout layout, const analysis::DfgTable& t,
                               const std::vector<double>& sheen) {
  std::vector<double> v;
  v.reserve(t.cells.size() * 3);
  for (size_t k = 0; k < t.cells.size(); ++k) {
    const auto& c = t.cells[k];
    using fresnel::Term;
    if (layout == DfgLayout::SplitSum)
      v.insert(v.end(), c.v.begin(), c.v.end());
    else
      v.insert(v.end(), {c[Term::Schlick], c[Term::One] + c[Term::Schlick], sheen[k]});
  }
  return v;
}

std::string comment_lines(const DfgText& d, const char* prefix) {
  return fmt::format("{0}axes: {1}\n{0}channels: {2}\n{0}shader: {3}\n", prefix, d.axes, d.channels,
                     d.shader);
}

std::string dfg_csv(DfgLayout layout, const analysis::DfgTable& t,
                    const std::vector<double>& values) {
  const auto& g = t.grid;
  analysis::Table tab;
  tab.name = "dfg";
  tab.columns = {col("nov"), col("perceptual_roughness"), col("alpha")};
  for (const auto& name : dfg_channel_names(layout)) tab.columns.push_back(col(name.c_str()));
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i) {
      const size_t k = static_cast<size_t>(g.index(i, j)) * 3;
      tab.rows.push_back({g.nov[i], g.perceptual_roughness[j], g.alpha[j], values[k], values[k + 1],
                          values[k + 2]});
    }
  return comment_lines(dfg_text(layout, g), "# ") + to_csv(tab);
}

ExrImage dfg_texture(DfgLayout layout, const analysis::DfgTable& t,
                     const std::vector<double>& values) {
  const auto& g = t.grid;
  const Axes axes{"nov",
                  g.nov.front(),
                  g.nov.back(),
                  kRoughnessAxis,
                  g.perceptual_roughness.front(),
                  g.perceptual_roughness.back()};
  const DfgText text = dfg_text(layout, g);
  auto img = texture(layout == DfgLayout::SplitSum ? "dfg" : "dfg_filament", g.size,
                     {"R", "G", "B"}, axes, g.convention, text.channels);
  img.string_attributes.emplace_back("fresnelLab:shader", text.shader);
  for (double v : values) img.pixels.push_back(static_cast<float>(v));
  return img;
}

// The C++ array body: `per_line` texels per line, each value printed by `value`.
template <class Print>
std::string array_body(size_t texels, int per_line, Print value) {
  std::string s;
  for (size_t k = 0; k < texels; ++k) {
    if (k % per_line == 0) s += k ? "\n   " : "   ";
    for (int c = 0; c < 3; ++c) s += " " + value(3 * k + c) + ",";
  }
  return s + "\n";
}

std::string filament_inc(const analysis::DfgTable& t, const std::vector<float>& values) {
  std::string s = fmt::format(
      "// generated by `fresnel-lab lut dfg --layout filament --size {}`: Filament's DFG LUT as "
      "an RGB16F texture, in GL order (half-float bit patterns, 3 per texel)\n",
      t.grid.size);
  s += comment_lines(dfg_text(DfgLayout::Filament, t.grid), "// ");
  return s + array_body(values.size() / 3, 4,
                        [&](size_t k) { return fmt::format("0x{:04x}", half_bits(values[k])); });
}

std::string filament_header(const analysis::DfgTable& t, const std::vector<float>& values) {
  const int n = t.grid.size;
  std::string s = fmt::format(
      "// Generated by `fresnel-lab lut dfg --layout filament --size {}`: Filament's DFG LUT, "
      "RGB16F, GL order; texel (j * size + i) * 3, half-float bit patterns.\n",
      n);
  s += comment_lines(dfg_text(DfgLayout::Filament, t.grid), "// ");
  s += fmt::format(
      "#pragma once\n\n#include <cstdint>\n\nnamespace fresnel_lab {{\n\nconstexpr int kDfgLutSize "
      "= {0};\n"
      "constexpr std::uint16_t kDfgLut[{0} * {0} * 3] = {{\n",
      n);
  s += array_body(values.size() / 3, 4,
                  [&](size_t k) { return fmt::format("0x{:04x}", half_bits(values[k])); });
  return s + "};\n\n}  // namespace fresnel_lab\n";
}

// ----- ltc-moments

std::string moments_csv(const analysis::MomentsTable& t) {
  const auto& g = t.grid;
  analysis::Table tab;
  tab.name = "ltc-moments";
  tab.columns = {col("nov"), col("perceptual_roughness"), col("alpha")};
  for (const auto& term : fresnel::kTermRegistry) tab.columns.push_back(col(term.ltc_channel));
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i) {
      const auto& c = t.cells[g.index(i, j)];
      tab.rows.push_back({g.nov[i], g.perceptual_roughness[j], g.alpha[j]});
      tab.rows.back().insert(tab.rows.back().end(), c.v.begin(), c.v.end());
    }
  return to_csv(tab);
}

ExrImage moments_texture(const analysis::MomentsTable& t) {
  const auto& g = t.grid;
  auto img = texture("ltc-moments", g.size, {"R", "G", "B"}, kLtcAxes, g.convention,
                     "R = n_D = integral rho cos, G = f_D = integral (1 - <v,h>)^5 rho cos, "
                     "B = l_D = integral <v,h> (1 - <v,h>)^6 rho cos");
  for (int i = 0; i < g.size; ++i)
    for (int j = 0; j < g.size; ++j) {
      const auto& c = t.cells[g.index(i, j)];
      for (double x : c.v) img.pixels.push_back(static_cast<float>(x));
    }
  return img;
}

// ----- ltc

// The sphere table shares the texel: its axes are texel x → z, texel y → len.
double sphere_at(const analysis::LtcTable& t, int i, int j) {
  return t.sphere_form_factor[static_cast<size_t>(i) * t.grid.size + j];
}

std::string ltc_csv(const analysis::LtcTable& t) {
  const auto& g = t.grid;
  const int n = g.size;
  analysis::Table tab;
  tab.name = "ltc";
  tab.columns = {col("nov"),     col("perceptual_roughness"),
                 col("alpha"),   col("inv_m00"),
                 col("inv_m20"), col("inv_m02"),
                 col("inv_m22"), col("m11"),
                 col("m22"),     col("m13"),
                 col("m31")};
  for (const auto& term : fresnel::kTermRegistry) tab.columns.push_back(col(term.ltc_channel));
  tab.columns.insert(tab.columns.end(), {col("sphere_z"),
                                         col("sphere_len"),
                                         col("sphere_form_factor"),
                                         col("heldout_error"),
                                         {"iterations", 0},
                                         {"termination"}});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int k = g.index(i, j);
      const auto& c = t.cells[k];
      const auto& m = t.moments[k];
      tab.rows.push_back({g.nov[i], g.perceptual_roughness[j], g.alpha[j], c.inv_packed[0],
                          c.inv_packed[1], c.inv_packed[2], c.inv_packed[3], c.params.m11,
                          c.params.m22, c.params.m13, c.params.m31});
      auto& row = tab.rows.back();
      row.insert(row.end(), m.v.begin(), m.v.end());
      row.insert(row.end(),
                 {2.0 * j / (n - 1) - 1.0, static_cast<double>(i) / (n - 1), sphere_at(t, i, j),
                  c.fit_error, static_cast<long long>(c.fit.iterations), c.fit.termination});
    }
  return to_csv(tab);
}

// ltc_1 (the normalized inverse matrix) and ltc_2 (the moments and the sphere form factor).
std::pair<ExrImage, ExrImage> ltc_textures(const analysis::LtcTable& t) {
  const auto& g = t.grid;
  auto tex1 = texture(
      "ltc_1", g.size, {"R", "G", "B", "A"}, kLtcAxes, g.convention,
      "inverse LTC matrix M^-1 normalized by M^-1[1][1], row-major indices: R = M^-1[0][0], "
      "G = M^-1[2][0], B = M^-1[0][2], A = M^-1[2][2]; shader: mat3(vec3(R, 0, G), vec3(0, 1, 0), "
      "vec3(B, 0, A))");
  auto tex2 =
      texture("ltc_2", g.size, {"R", "G", "B", "A"}, kLtcAxes, g.convention,
              "R = n_D, G = f_D, B = l_D (the F82 moment), A = horizon-clipped sphere form factor "
              "(its own axes: x → z = 2x - 1, y → length of the vector form factor)");
  for (int i = 0; i < g.size; ++i)
    for (int j = 0; j < g.size; ++j) {
      const int k = g.index(i, j);
      for (double v : t.cells[k].inv_packed) tex1.pixels.push_back(static_cast<float>(v));
      const auto& m = t.moments[k];
      for (double x : m.v) tex2.pixels.push_back(static_cast<float>(x));
      tex2.pixels.push_back(static_cast<float>(sphere_at(t, i, j)));
    }
  return {std::move(tex1), std::move(tex2)};
}

std::string ltc_fit_message(const analysis::LtcTable& t) {
  double sum = 0, max = 0;
  for (const auto& c : t.cells) {
    sum += c.fit_error;
    max = std::max(max, c.fit_error);
  }
  return fmt::format("lut ltc: held-out error (relative L3) mean {:.4f}, max {:.4f} over {} cells",
                     sum / static_cast<double>(t.cells.size()), max, t.cells.size());
}

}  // namespace

DfgLayout dfg_layout_from_name(const std::string& name) {
  if (name == "split-sum") return DfgLayout::SplitSum;
  if (name == "filament") return DfgLayout::Filament;
  throw InputError(fmt::format("--layout must be split-sum or filament, not '{}'", name));
}

std::string dfg_header(const analysis::DfgTable& t) {
  const auto& g = t.grid;
  std::string s = fmt::format(
      "// Generated by `fresnel-lab lut dfg --size {}`: the split-sum DFG table; texel (j * size + "
      "i) * 3.\n",
      g.size);
  s += comment_lines(dfg_text(DfgLayout::SplitSum, g), "// ");
  s += fmt::format(
      "#pragma once\n\nnamespace fresnel_lab {{\n\nconstexpr int kDfgLutSize = {0};\n"
      "constexpr float kDfgLut[{0} * {0} * 3] = {{\n",
      g.size);
  const auto values = dfg_values(DfgLayout::SplitSum, t, {});
  s += array_body(values.size() / 3, static_cast<int>(g.size),
                  [&](size_t k) { return fmt::format("{:.9e}f", static_cast<float>(values[k])); });
  return s + "};\n\n}  // namespace fresnel_lab\n";
}

std::vector<float> filament_dfg_values(const analysis::DfgTable& t,
                                       const std::vector<double>& sheen) {
  const auto v = dfg_values(DfgLayout::Filament, t, sheen);
  return std::vector<float>(v.begin(), v.end());
}

Output dfg_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const DfgLayout layout = dfg_layout_from_name(request.layout);
  const LutRequest r =
      sized(request, layout == DfgLayout::Filament ? kFilamentDfgSize : kDefaultSize);
  const std::string ext = layout == DfgLayout::Filament
                              ? output_extension(r.out, {".exr", ".csv", ".h", ".inc"})
                              : output_extension(r.out, {".exr", ".csv", ".h"});
  const auto grid = analysis::dfg_grid(r.size);
  const auto opts = lut_options(r, progress);
  const auto t = analysis::dfg_table(grid, opts);
  const auto sheen =
      layout == DfgLayout::Filament ? analysis::sheen_dfg_table(grid, opts) : std::vector<double>{};
  const auto values = dfg_values(layout, t, sheen);
  std::string bytes;
  if (ext == ".csv")
    bytes = dfg_csv(layout, t, values);
  else if (ext == ".exr")
    bytes = encode_exr(dfg_texture(layout, t, values));
  else if (layout == DfgLayout::SplitSum)
    bytes = dfg_header(t);
  else if (ext == ".inc")
    bytes = filament_inc(t, filament_dfg_values(t, sheen));
  else
    bytes = filament_header(t, filament_dfg_values(t, sheen));
  return one_file(fmt::format("lut dfg ({})", r.layout), r.out, bytes);
}

Output moments_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const LutRequest r = sized(request, kDefaultSize);
  const std::string ext = output_extension(r.out, {".exr", ".csv"});
  const auto t = analysis::moments_table(analysis::ltc_grid(r.size), lut_options(r, progress));
  return one_file("lut ltc-moments", r.out,
                  ext == ".csv" ? moments_csv(t) : encode_exr(moments_texture(t)));
}

Output ltc_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const LutRequest r = sized(request, kDefaultSize);
  const std::string ext = output_extension(r.out, {".exr", ".csv"});
  const auto t = analysis::fit_ltc_table(r.size, lut_options(r, progress));
  Output o;
  if (ext == ".csv") {
    o = one_file("lut ltc", r.out, ltc_csv(t));
  } else {
    const auto stem =
        (std::filesystem::path(r.out).parent_path() / std::filesystem::path(r.out).stem()).string();
    const auto [tex1, tex2] = ltc_textures(t);
    o.files = {{stem + "_1.exr", encode_exr(tex1)},
               {stem + "_2.exr", encode_exr(tex2)},
               {stem + ".csv", ltc_csv(t)}};
    o.messages.push_back("lut ltc: wrote " + file_list(o.files));
  }
  o.messages.push_back(ltc_fit_message(t));
  return o;
}

// ----- energy

namespace {

constexpr const char* kEnergyAxes =
    "x = n.v, y = perceptual roughness (alpha = roughness^2), texel centres; rows from smooth to "
    "rough (the first row is texture v = 0, GL order)";
constexpr const char* kEnergyChannels =
    "R = E = integral rho cos (the GGX lobe's directional albedo, height-correlated Smith, no "
    "Fresnel), G = E_avg = 2 integral_0^1 E(mu) mu dmu (the same for every texel of a row)";
constexpr const char* kEnergyShader =
    "vec2 e = textureLod(energyLut, vec2(NoV, perceptualRoughness), 0.0).rg; Kulla-Conty: f_ms = "
    "(1 - E(NoV)) (1 - E(NoL)) / (pi (1 - e.g)) * F_avg^2 e.g / (1 - F_avg (1 - e.g))";

std::string energy_csv(const analysis::EnergyTable& t) {
  const auto& g = t.grid;
  analysis::Table tab;
  tab.name = "energy";
  tab.columns = {col("nov"), col("perceptual_roughness"), col("alpha"), col("e"), col("e_avg")};
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i)
      tab.rows.push_back(
          {g.nov[i], g.perceptual_roughness[j], g.alpha[j], t.e[g.index(i, j)], t.e_avg[j]});
  return fmt::format("# axes: {}\n# channels: {}\n# shader: {}\n", kEnergyAxes, kEnergyChannels,
                     kEnergyShader) +
         to_csv(tab);
}

ExrImage energy_texture(const analysis::EnergyTable& t) {
  const auto& g = t.grid;
  const Axes axes{"nov",
                  g.nov.front(),
                  g.nov.back(),
                  kRoughnessAxis,
                  g.perceptual_roughness.front(),
                  g.perceptual_roughness.back()};
  auto img = texture("energy", g.size, {"R", "G"}, axes, g.convention, kEnergyChannels);
  img.string_attributes.emplace_back("fresnelLab:shader", kEnergyShader);
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i)
      img.pixels.insert(img.pixels.end(),
                        {static_cast<float>(t.e[g.index(i, j)]), static_cast<float>(t.e_avg[j])});
  return img;
}

// `per_line` floats per line.
std::string float_lines(const std::vector<double>& v, size_t per_line) {
  std::string s;
  for (size_t k = 0; k < v.size(); ++k) {
    if (k % per_line == 0) s += k ? "\n   " : "   ";
    s += fmt::format(" {:.9e}f,", static_cast<float>(v[k]));
  }
  return s + "\n";
}

std::string energy_header(const analysis::EnergyTable& t) {
  const int n = t.grid.size;
  std::string s = fmt::format(
      "// Generated by `fresnel-lab lut energy --size {}`: Kulla-Conty's E(n.v, roughness), texel "
      "j * size + i, and E_avg(roughness), texel j.\n// axes: {}\n// channels: {}\n// shader: "
      "{}\n",
      n, kEnergyAxes, kEnergyChannels, kEnergyShader);
  s += fmt::format(
      "#pragma once\n\nnamespace fresnel_lab {{\n\nconstexpr int kEnergyLutSize = {0};\n"
      "constexpr float kEnergyLut[{0} * {0}] = {{\n",
      n);
  s += float_lines(t.e, static_cast<size_t>(n));
  s += fmt::format("}};\nconstexpr float kEnergyAverage[{}] = {{\n", n);
  s += float_lines(t.e_avg, 8);
  return s + "};\n\n}  // namespace fresnel_lab\n";
}

}  // namespace

Output energy_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const LutRequest r = sized(request, kDefaultSize);
  const std::string ext = output_extension(r.out, {".exr", ".csv", ".h"});
  const auto t = analysis::energy_table(analysis::dfg_grid(r.size), lut_options(r, progress));
  std::string bytes = ext == ".csv"   ? energy_csv(t)
                      : ext == ".exr" ? encode_exr(energy_texture(t))
                                      : energy_header(t);
  return one_file("lut energy", r.out, std::move(bytes));
}

}  // namespace fl::report
