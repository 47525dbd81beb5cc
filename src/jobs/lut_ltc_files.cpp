// `lut ltc-moments` and `lut ltc`: the LTC-moment textures and the fitted LTC tables' files.
#include <fmt/format.h>

#include <filesystem>

#include "analysis/ltc/ltc_table.h"
#include "analysis/lut/lut_layout.h"
#include "documents/table_formats.h"
#include "fresnel/table_terms.h"
#include "jobs/lut_files.h"
#include "jobs/lut_texture.h"
#include "util/errors.h"

namespace fl::jobs {

using namespace lut_files;
namespace {

// The LTC texture layout (Heitz & Hill's ltc_code packTab): x = roughness (j), y = √(1 − n·v) (i).
const Axes kLtcAxes{kRoughnessAxis, 0.0, 1.0, "sqrt(1 - nov)", 0.0, 1.0};

// ----- ltc-moments

std::string moments_csv(const analysis::MomentsTable& t) {
  const auto& g = t.grid;
  Table tab;
  tab.name = "ltc-moments";
  tab.columns = {col("nov"), col("perceptual_roughness"), col("alpha")};
  for (const auto& term : fresnel::kTermRegistry) tab.columns.push_back(col(term.ltc.channel));
  for (int j = 0; j < g.size; ++j)
    for (int i = 0; i < g.size; ++i) {
      const auto& c = t.cells[g.index(i, j)];
      tab.rows.push_back({g.nov[i], g.perceptual_roughness[j], g.alpha[j]});
      tab.rows.back().insert(tab.rows.back().end(), c.v.begin(), c.v.end());
    }
  return documents::to_csv(tab);
}

// "R = n_D = integral rho cos, ..." for the moments of one LTC texture.
std::string moments_channel_text(const std::string& texture) {
  std::string s;
  for (const auto* t : texture_terms(false, texture))
    s += fmt::format("{}{} = {} = integral {}rho cos", s.empty() ? "" : ", ",
                     upper(t->ltc.component), t->ltc.symbol, t->ltc.integrand);
  return s;
}

io::ExrImage moments_texture(const analysis::MomentsTable& t, const std::string& name) {
  const auto& g = t.grid;
  auto img = texture("ltc-moments", g.size, exr_channels(false, name), kLtcAxes, g.convention,
                     moments_channel_text(name));
  const auto terms = texture_terms(false, name);
  for (int i = 0; i < g.size; ++i)
    for (int j = 0; j < g.size; ++j) {
      const auto& c = t.cells[g.index(i, j)];
      for (const auto* term : terms) img.pixels.push_back(static_cast<float>(c[term->term]));
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
  Table tab;
  tab.name = "ltc";
  tab.columns = {col("nov"),     col("perceptual_roughness"),
                 col("alpha"),   col("inv_m00"),
                 col("inv_m20"), col("inv_m02"),
                 col("inv_m22"), col("m11"),
                 col("m22"),     col("m13"),
                 col("m31")};
  for (const auto& term : fresnel::kTermRegistry) tab.columns.push_back(col(term.ltc.channel));
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
  return documents::to_csv(tab);
}

// ltc_2's description: its terms' moments and the sphere form factor in A.
std::string ltc_2_text() {
  std::string s;
  for (const auto* t : texture_terms(false, "ltc_2"))
    s += fmt::format("{}{} = {}{}", s.empty() ? "" : ", ", upper(t->ltc.component), t->ltc.symbol,
                     t->ltc.note);
  return s +
         ", A = horizon-clipped sphere form factor (its own axes: x → z = 2x - 1, y → length of "
         "the vector form factor)";
}

// The textures beside the matrix: ltc_2 (its terms' moments and the sphere form factor) and the
// other terms' textures (ltc_3, ...), in analysis::term_texture_names order.
std::vector<io::ExrImage> moment_textures(const analysis::LtcTable& t) {
  const auto& g = t.grid;
  std::vector<io::ExrImage> out;
  for (const auto& name : analysis::term_texture_names(false)) {
    const bool second = name == "ltc_2";
    auto channels = exr_channels(false, name);
    if (second) channels.push_back("A");
    out.push_back(texture(name, g.size, channels, kLtcAxes, g.convention,
                          second ? ltc_2_text() : moments_channel_text(name)));
    const auto terms = texture_terms(false, name);
    for (int i = 0; i < g.size; ++i)
      for (int j = 0; j < g.size; ++j) {
        const int k = g.index(i, j);
        for (const auto* term : terms)
          out.back().pixels.push_back(static_cast<float>(t.moments[k][term->term]));
        if (second) out.back().pixels.push_back(static_cast<float>(sphere_at(t, i, j)));
      }
  }
  return out;
}

// ltc_1: the normalized inverse matrix.
io::ExrImage matrix_texture(const analysis::LtcTable& t) {
  const auto& g = t.grid;
  auto tex1 = texture(
      "ltc_1", g.size, {"R", "G", "B", "A"}, kLtcAxes, g.convention,
      "inverse LTC matrix M^-1 normalized by M^-1[1][1], row-major indices: R = M^-1[0][0], "
      "G = M^-1[2][0], B = M^-1[0][2], A = M^-1[2][2]; shader: mat3(vec3(R, 0, G), vec3(0, 1, 0), "
      "vec3(B, 0, A))");
  for (int i = 0; i < g.size; ++i)
    for (int j = 0; j < g.size; ++j)
      for (double v : t.cells[g.index(i, j)].inv_packed)
        tex1.pixels.push_back(static_cast<float>(v));
  return tex1;
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

io::Output moments_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const LutRequest r = sized(request, kDefaultSize);
  const std::string ext = io::output_extension(r.out, {".exr", ".csv", ".h"});
  const std::string symbol = header_symbol(r, ext, "fresnel_lab_ltc_moments");
  const auto t = analysis::moments_table(analysis::ltc_grid(r.size), lut_options(r, progress));
  if (ext == ".csv") return one_file("lut ltc-moments", r.out, moments_csv(t));
  io::Output o;
  const auto textures = analysis::term_texture_names(false);
  for (size_t k = 0; k < textures.size(); ++k)
    o.files.emplace_back(texture_path(r.out, textures[k], k),
                         texture_bytes(moments_texture(t, textures[k]), ext,
                                       {k ? symbol + suffix(textures[k]) : symbol,
                                        lut_command("ltc-moments", r, symbol)},
                                       r.half));
  o.messages.push_back("lut ltc-moments: wrote " + io::file_list(o.files));
  return o;
}

io::Output ltc_lut(const LutRequest& request, const analysis::LutProgress& progress) {
  const LutRequest r = sized(request, kDefaultSize);
  const std::string ext = io::output_extension(r.out, {".exr", ".csv", ".h"});
  const std::string symbol = header_symbol(r, ext, "fresnel_lab_ltc");
  const auto t = analysis::fit_ltc_table(r.size, lut_options(r, progress));
  io::Output o;
  if (ext == ".csv") {
    o = one_file("lut ltc", r.out, ltc_csv(t));
  } else {
    const std::filesystem::path out(r.out);
    const auto stem = (out.parent_path() / out.stem()).string();
    const documents::CHeader header{symbol, lut_command("ltc", r, symbol)};
    const auto names = analysis::term_texture_names(false);
    const auto images = moment_textures(t);
    for (const std::string e : {ext, std::string(".h")}) {
      if (e != ext && !(r.headers && ext == ".exr")) continue;
      auto add = [&](const std::string& texture, const io::ExrImage& img) {
        documents::CHeader h = header;
        h.symbol += suffix(texture);
        o.files.emplace_back(stem + suffix(texture) + e, texture_bytes(img, e, h, r.half));
      };
      add("ltc_1", matrix_texture(t));
      for (size_t k = 0; k < names.size(); ++k) add(names[k], images[k]);
    }
    if (ext == ".exr") o.files.emplace_back(stem + ".csv", ltc_csv(t));
    o.messages.push_back("lut ltc: wrote " + io::file_list(o.files));
  }
  o.messages.push_back(ltc_fit_message(t));
  return o;
}

}  // namespace fl::jobs
