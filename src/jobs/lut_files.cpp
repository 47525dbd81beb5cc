#include "jobs/lut_files.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "analysis/lut/lut_layout.h"
#include "analysis/tables/table_layouts.h"
#include "documents/c_header.h"
#include "documents/table_formats.h"
#include "fresnel/table_terms.h"
#include "io/exr.h"
#include "jobs/lut_texture.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::jobs {
namespace lut_files {

// The request with its size (default_size when not given), checked.
LutRequest sized(LutRequest r, int default_size) {
  if (r.size == LutRequest::kSizeNotGiven) r.size = default_size;
  if (r.size < 2 || r.size > 4096)
    throw InputError(fmt::format("--size {} out of range (2 to 4096)", r.size));
  if (r.samples < kMinLutSamples)
    throw InputError(
        fmt::format("--samples {} is below {}: fewer samples per cell leave the table visibly "
                    "wrong ({} samples: DFG values off by up to 4e-3)",
                    r.samples, kMinLutSamples, kMinLutSamples));
  if (r.threads < 0)
    throw InputError(fmt::format("--threads {} must be 0 (all) or positive", r.threads));
  return r;
}

analysis::LutOptions lut_options(const LutRequest& r, const analysis::LutProgress& progress) {
  return {r.samples, r.threads, progress};
}

// Nine significant digits: every value a float holds, small ones included.
Column col(const char* name) {
  return {name, 9, true, true};
}

// Texture-axis attributes shared by every EXR written here.

io::ExrImage texture(const std::string& table, int size, std::vector<std::string> channels,
                     const Axes& a, const std::string& grid, const std::string& channel_text) {
  io::ExrImage img;
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

// The uv a shader reads a DFG-grid texture at: (n·v, roughness) remapped to the texel centres of
// endpoints, or as it is for texel centres (the Filament layout).
std::string dfg_uv_text(const analysis::LutGrid& g) {
  if (g.placement == analysis::TexelPlacement::Centres) return "vec2(NoV, perceptualRoughness)";
  return fmt::format("vec2(NoV, perceptualRoughness) * ({0}.0 / {1}.0) + 0.5 / {1}.0", g.size - 1,
                     g.size);
}

// The DFG grid's texture axes: x = n·v, y = perceptual roughness, at the grid's first and last
// texels.
Axes dfg_axes(const analysis::LutGrid& g) {
  return {"nov",
          g.nov.front(),
          g.nov.back(),
          kRoughnessAxis,
          g.perceptual_roughness.front(),
          g.perceptual_roughness.back()};
}

io::Output one_file(const std::string& what, const std::string& path, std::string bytes) {
  io::Output o;
  o.files.emplace_back(path, std::move(bytes));
  o.messages.push_back(fmt::format("{}: wrote {}", what, path));
  return o;
}

// ----- the table terms' textures

// The table terms a texture holds (analysis::term_texture_names), in registry order.
std::vector<const fresnel::TermSpec*> texture_terms(bool dfg, const std::string& texture) {
  std::vector<const fresnel::TermSpec*> out;
  for (const auto& t : fresnel::kTermRegistry)
    if (texture == (dfg ? t.dfg.texture : t.ltc.texture)) out.push_back(&t);
  return out;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// The EXR channels of a texture's terms: their components, upper case.
std::vector<std::string> exr_channels(bool dfg, const std::string& texture) {
  std::vector<std::string> out;
  for (const auto* t : texture_terms(dfg, texture))
    out.push_back(upper(dfg ? t->dfg.component : t->ltc.component));
  return out;
}

// A texture's suffix after its table's name: dfg_2 → _2, ltc_1 → _1.
std::string suffix(const std::string& texture) {
  return texture.substr(texture.find('_'));
}

// Where texture number k (0, 1, ...) of a table goes when the table is written to `out`: out
// itself for the first, else STEM + the texture's suffix (dfg_2 → STEM_2.exr, or STEM_2.h).
std::string texture_path(const std::string& out, const std::string& texture, size_t k) {
  if (k == 0) return out;
  const std::filesystem::path p(out);
  return (p.parent_path() / p.stem()).string() + suffix(texture) + p.extension().string();
}

// The C symbol of a table's headers (request.symbol or default_symbol), checked; InputError for a
// symbol given with another output type.
std::string header_symbol(const LutRequest& r, const std::string& ext, const char* default_symbol) {
  if (r.symbol.empty()) return default_symbol;
  if (ext != ".h") throw InputError("--symbol names the arrays of .h output only");
  documents::check_c_symbol(r.symbol);
  return r.symbol;
}

// A texture as EXR bytes, or as a C header for `.h` output; half floats when the request asks.
std::string texture_bytes(io::ExrImage img, const std::string& ext, documents::CHeader header,
                          bool half) {
  img.half = header.half = half;
  return ext == ".h" ? documents::c_header(img, header) : io::encode_exr(img);
}

// "fresnel-lab lut NAME --size N [...]": what wrote a header.
std::string lut_command(const char* name, const LutRequest& r, const std::string& symbol) {
  return fmt::format(
      "fresnel-lab lut {} --size {}{}{}{} --symbol {}", name, r.size,
      std::string(name) == "dfg" && r.layout != "split-sum" ? " --layout " + r.layout
                                                            : std::string(),
      r.dielectric ? fmt::format(" --dielectric --slices {}", r.slices) : std::string(),
      r.half ? " --storage half" : "", symbol);
}

}  // namespace lut_files
using namespace lut_files;
namespace {

// ----- dfg

// What a DFG file says about itself: its axes, channels and the shader code that reads it.
struct DfgText {
  std::string axes, channels, shader;
};

// "R = dfg1 = integral (1 - Fc) rho cos, ..." for one split-sum texture.
std::string dfg_channel_text(const std::string& texture) {
  std::string s;
  for (const auto* t : texture_terms(true, texture))
    s += fmt::format("{}{} = {} = integral {}rho cos", s.empty() ? "" : ", ",
                     upper(t->dfg.component), t->dfg.channel, t->dfg.integrand);
  return s +
         ", with Fc = (1 - mu)^5, mu = v.h, rho cos the GGX lobe with height-correlated Smith "
         "masking";
}

// How a shader reads a split-sum texture after the first: a model weighing term t by w_t adds
// w_t times the term's channel.
std::string dfg_extra_shader_text(const analysis::LutGrid& g, const std::string& texture) {
  return fmt::format(
      "vec3 {0} = textureLod({0}_lut, {1}, 0.0).rgb; a model weighing a term by w adds w * its "
      "channel",
      texture, dfg_uv_text(g));
}

DfgText dfg_text(DfgLayout layout, const analysis::LutGrid& g, const std::string& texture) {
  const std::string axes = fmt::format(
      "x = n.v, y = perceptual roughness, {}; rows from smooth to rough (the first row is texture "
      "v = 0, GL order)",
      g.convention);
  if (layout == DfgLayout::SplitSum && texture != "dfg")
    return {axes, dfg_channel_text(texture), dfg_extra_shader_text(g, texture)};
  if (layout == DfgLayout::SplitSum)
    return {axes, dfg_channel_text(texture),
            fmt::format("vec3 dfg = textureLod(dfgLut, {}, 0.0).rgb; Schlick: E = f0 * dfg.r + "
                        "dfg.g; Hoffman's F82 model: E = f0 * dfg.r + dfg.g - a * dfg.b, a = "
                        "(823543/46656) (f0 - f82) + (49/6) (1 - f0)",
                        dfg_uv_text(g))};
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

// The texture values of one split-sum texture, its channels per texel in file order
// (roughness-major, like the cells).
std::vector<double> dfg_values(const analysis::DfgTable& t, const std::string& texture) {
  const auto terms = texture_terms(true, texture);
  std::vector<double> v;
  v.reserve(t.cells.size() * terms.size());
  for (const auto& c : t.cells)
    for (const auto* term : terms) v.push_back(c[term->term]);
  return v;
}

// Filament's layout: three values per texel.
std::vector<double> filament_values(const analysis::DfgTable& t, const std::vector<double>& sheen) {
  using fresnel::Term;
  std::vector<double> v;
  v.reserve(t.cells.size() * 3);
  for (size_t k = 0; k < t.cells.size(); ++k) {
    const auto& c = t.cells[k];
    v.insert(v.end(), {c[Term::Schlick], c[Term::One] + c[Term::Schlick], sheen[k]});
  }
  return v;
}

std::string comment_lines(const DfgText& d, const char* prefix) {
  return fmt::format("{0}axes: {1}\n{0}channels: {2}\n{0}shader: {3}\n", prefix, d.axes, d.channels,
                     d.shader);
}

// The split-sum CSV: every term's channel, its texture's description per texture.
std::string split_sum_csv(const analysis::DfgTable& t) {
  const auto& g = t.grid;
  Table tab;
  tab.name = "dfg";
  tab.columns = {col("nov"), col("perceptual_roughness"), col("alpha")};
  for (const auto& term : fresnel::kTermRegistry) tab.columns.push_back(col(term.dfg.channel));
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i) {
      const auto& c = t.cells[g.index(i, j)];
      tab.rows.push_back({g.nov[i], g.perceptual_roughness[j], g.alpha[j]});
      tab.rows.back().insert(tab.rows.back().end(), c.v.begin(), c.v.end());
    }
  std::string head;
  for (const auto& name : analysis::term_texture_names(true))
    head += comment_lines(dfg_text(DfgLayout::SplitSum, g, name), "# ");
  return head + documents::to_csv(tab);
}

std::string filament_csv(const analysis::DfgTable& t, const std::vector<double>& values) {
  const auto& g = t.grid;
  Table tab;
  tab.name = "dfg";
  tab.columns = {col("nov"),      col("perceptual_roughness"),
                 col("alpha"),    col("dfg_fc"),
                 col("dfg_norm"), col("dfg_sheen")};
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i) {
      const size_t k = static_cast<size_t>(g.index(i, j)) * 3;
      tab.rows.push_back({g.nov[i], g.perceptual_roughness[j], g.alpha[j], values[k], values[k + 1],
                          values[k + 2]});
    }
  return comment_lines(dfg_text(DfgLayout::Filament, g, "dfg"), "# ") + documents::to_csv(tab);
}

io::ExrImage dfg_texture(DfgLayout layout, const analysis::DfgTable& t, const std::string& name,
                         const std::vector<double>& values) {
  const auto& g = t.grid;
  const Axes axes = dfg_axes(g);
  const DfgText text = dfg_text(layout, g, name);
  const bool split = layout == DfgLayout::SplitSum;
  auto img = texture(split ? name : "dfg_filament", g.size,
                     split ? exr_channels(true, name) : std::vector<std::string>{"R", "G", "B"},
                     axes, g.convention, text.channels);
  img.string_attributes.emplace_back("fresnelLab:shader", text.shader);
  for (double v : values) img.pixels.push_back(static_cast<float>(v));
  return img;
}

std::string filament_inc(const analysis::DfgTable& t, const std::vector<float>& values) {
  std::string s = fmt::format(
      "// generated by `fresnel-lab lut dfg --layout filament --size {}`: Filament's DFG LUT as "
      "an RGB16F texture, in GL order (half-float bit patterns, 3 per texel)\n",
      t.grid.size);
  s += comment_lines(dfg_text(DfgLayout::Filament, t.grid, "dfg"), "// ");
  return s + documents::c_array_values(values, 3, 4, true);
}

}  // namespace

DfgLayout dfg_layout_from_name(const std::string& name) {
  const std::vector<NameChoice> choices = {{"split-sum", {"splitsum"}}, {"filament", {}}};
  const auto match = match_name(name, choices);
  if (!match) throw InputError("--layout: " + unknown_name_message("layout", name, choices));
  return *match == "filament" ? DfgLayout::Filament : DfgLayout::SplitSum;
}

std::vector<float> filament_dfg_values(const analysis::DfgTable& t,
                                       const std::vector<double>& sheen) {
  const auto v = filament_values(t, sheen);
  return std::vector<float>(v.begin(), v.end());
}

// The split-sum textures: out.exr, then STEM_2.exr, ... (or out.h, STEM_2.h, ...).
io::Output split_sum_textures(const LutRequest& r, const std::string& ext,
                              const std::string& symbol, const analysis::DfgTable& t) {
  io::Output o;
  const auto textures = analysis::term_texture_names(true);
  for (size_t k = 0; k < textures.size(); ++k) {
    const std::string sym = k ? symbol + suffix(textures[k]) : symbol;
    o.files.emplace_back(
        texture_path(r.out, textures[k], k),
        texture_bytes(dfg_texture(DfgLayout::SplitSum, t, textures[k], dfg_values(t, textures[k])),
                      ext, {sym, lut_command("dfg", r, symbol)}, r.half));
  }
  o.messages.push_back("lut dfg (split-sum): wrote " + io::file_list(o.files));
  return o;
}

io::Output dfg_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const DfgLayout layout = dfg_layout_from_name(request.layout);
  const LutRequest r =
      sized(request, layout == DfgLayout::Filament ? kFilamentDfgSize : kDefaultSize);
  const std::string ext = layout == DfgLayout::Filament
                              ? io::output_extension(r.out, {".exr", ".csv", ".h", ".inc"})
                              : io::output_extension(r.out, {".exr", ".csv", ".h"});
  const std::string symbol = header_symbol(
      r, ext, layout == DfgLayout::Filament ? "fresnel_lab_dfg_filament" : "fresnel_lab_dfg");
  const auto grid = layout == DfgLayout::Filament ? analysis::filament_dfg_grid(r.size)
                                                  : analysis::dfg_grid(r.size);
  // Filament's layout integrates two tables (GGX, then sheen): one bar over both, never restarting.
  const int stages = layout == DfgLayout::Filament ? 2 : 1;
  const auto stage = [&](int k) -> analysis::LutProgress {
    if (!progress) return {};
    return
        [&progress, k, stages](int done, int total) { progress(k * total + done, stages * total); };
  };
  auto opts = lut_options(r, stage(0));
  const auto t = analysis::dfg_table(grid, opts);
  if (layout == DfgLayout::SplitSum && ext != ".csv") {
    io::Output o = split_sum_textures(r, ext, symbol, t);
    if (r.headers && ext == ".exr") {
      LutRequest h = r;
      h.out = std::filesystem::path(r.out).replace_extension(".h").string();
      for (auto& f : split_sum_textures(h, ".h", symbol, t).files) o.files.push_back(std::move(f));
    }
    return o;
  }
  std::string bytes;
  if (layout == DfgLayout::SplitSum) {
    bytes = split_sum_csv(t);
  } else {
    opts.progress = stage(1);
    const auto sheen = analysis::sheen_dfg_table(grid, opts);
    const auto values = filament_values(t, sheen);
    if (ext == ".csv")
      bytes = filament_csv(t, values);
    else if (ext == ".exr")
      bytes = io::encode_exr(dfg_texture(layout, t, "dfg", values));
    else if (ext == ".inc")
      bytes = filament_inc(t, filament_dfg_values(t, sheen));
    else
      bytes = documents::c_header(dfg_texture(layout, t, "dfg", values),
                                  {symbol, lut_command("dfg", r, symbol), true});
  }
  return one_file(fmt::format("lut dfg ({})", r.layout), r.out, bytes);
}

std::string table_error_line(const analysis::Context& ctx,
                             const std::vector<analysis::MaterialStudy>& studies,
                             const LutRequest& r, analysis::Lighting lighting) {
  const int size = r.size > 0 ? r.size : kDefaultSize;
  const auto storage = r.half ? analysis::TexelStorage::Half : analysis::TexelStorage::Float;
  const auto e =
      analysis::table_error_summary(ctx, studies, analysis::engine_tables(size, storage), lighting);
  return fmt::format(
      "as rendered from these {}² {} tables under {}, over the catalog's {} metals: the tables' "
      "own error (against the exact lobe integrals), median RMS ΔE2000 Schlick {:.4f}, basis4 "
      "{:.4f} (largest {:.4f})",
      size, analysis::texel_storage_name(storage), analysis::lighting_name(lighting), e.metals,
      e.schlick_median, e.basis4_median, e.basis4_max);
}

}  // namespace fl::jobs
