#pragma once
// The pieces every `lut` table's files share (jobs/lut_files.cpp defines them; the DFG's files are
// there too, the LTC's in lut_ltc_files.cpp, the energy tables' in lut_energy_files.cpp and
// lut_energy_dielectric.cpp): the request's
// checks, the texture and its attributes, CSV columns, header symbols and the command line a
// header names.
#include <string>
#include <vector>

#include "analysis/lut/lut.h"
#include "documents/c_header.h"
#include "fresnel/table_terms.h"
#include "io/exr.h"
#include "io/writer.h"
#include "jobs/lut_files.h"
#include "util/table.h"

namespace fl::jobs::lut_files {

inline constexpr int kDefaultSize = 64;
inline constexpr const char* kRoughnessAxis = "perceptual_roughness";

// The request with its size (default_size when 0), checked (InputError).
LutRequest sized(LutRequest r, int default_size);
analysis::LutOptions lut_options(const LutRequest& r, const analysis::LutProgress& progress);
// A CSV column of nine significant digits: every value a float holds, small ones included.
Column col(const char* name);

// Texture-axis attributes shared by every EXR written here.
struct Axes {
  std::string x_axis;
  double x_min, x_max;
  std::string y_axis;
  double y_min, y_max;
};
// A size × size texture with the fresnelLab:* attributes (table, axes, grid, channels, row order).
io::ExrImage texture(const std::string& table, int size, std::vector<std::string> channels,
                     const Axes& a, const std::string& grid, const std::string& channel_text);
// The uv a shader reads a DFG-grid texture at (endpoints remapped to texel centres).
std::string dfg_uv_text(const analysis::LutGrid& g);
// The DFG grid's texture axes: x = n·v, y = perceptual roughness.
Axes dfg_axes(const analysis::LutGrid& g);
io::Output one_file(const std::string& what, const std::string& path, std::string bytes);
// The C symbol of a table's headers (request.symbol or default_symbol), checked; InputError for a
// symbol given with another output type.
std::string header_symbol(const LutRequest& r, const std::string& ext, const char* default_symbol);
// A texture as EXR bytes, or as a C header for `.h` output; half floats when `half`.
std::string texture_bytes(io::ExrImage img, const std::string& ext, documents::CHeader header,
                          bool half);
// The table terms a texture holds (analysis::term_texture_names), in registry order.
std::vector<const fresnel::TermSpec*> texture_terms(bool dfg, const std::string& texture);
std::string upper(std::string s);
// The EXR channels of a texture's terms: their components, upper case.
std::vector<std::string> exr_channels(bool dfg, const std::string& texture);
// A texture's suffix after its table's name: dfg_2 → _2, ltc_1 → _1.
std::string suffix(const std::string& texture);
// Where texture number k (0, 1, ...) of a table goes when the table is written to `out`: out
// itself for the first, else STEM + the texture's suffix (dfg_2 → STEM_2.exr, or STEM_2.h).
std::string texture_path(const std::string& out, const std::string& texture, size_t k);
// "fresnel-lab lut NAME --size N [...]": what wrote a header.
std::string lut_command(const char* name, const LutRequest& r, const std::string& symbol);

}  // namespace fl::jobs::lut_files
