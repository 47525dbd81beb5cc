#pragma once
// `lut dfg | ltc-moments | ltc`: the pre-integrated GGX tables (analysis/lut/lut.h) computed and
// written as EXR textures, CSV tables and C++ headers.
#include <string>
#include <vector>

#include "analysis/lut/energy.h"
#include "analysis/lut/lut.h"
#include "analysis/lut/rendered.h"
#include "analysis/study/study.h"
#include "io/writer.h"

namespace fl::jobs {

// The layouts of `lut dfg`. split-sum: one channel per table term (fresnel::kTermRegistry) in its
// texture: dfg (R = dfg1 (scale), G = dfg2 (bias), B = dfg_f82, read as E = F0·R + G (Schlick),
// E = F0·R + G − a·B (Hoffman's F82)) and dfg_2 (the basis terms b1..b4). filament: Filament's
// multiscatter table as its shaders read it, R = dfg2 = ∫ Fc ρ cos, G = dfg1 + dfg2 = ∫ ρ cos, B =
// the sheen albedo; E = mix(dfg.xxx, dfg.yyy, F0), energy compensation 1 + F0 (1/dfg.y − 1).
enum class DfgLayout { SplitSum, Filament };
DfgLayout dfg_layout_from_name(
    const std::string& name);  // split-sum | filament (InputError otherwise)
// Filament's DFG_LUT_SIZE: the table its engine compiles in (128 × 128 RGB16F).
inline constexpr int kFilamentDfgSize = 128;

// The fewest quasi-Monte Carlo samples per cell `lut` takes: fewer leave a table visibly wrong.
// Measured: a 16² DFG table at 256 samples is off by up to 3.9e-3 from 8192 samples, at 1024 by
// 1.1e-3 (docs/engines.md).
inline constexpr int kMinLutSamples = 256;

struct LutRequest {
  static constexpr int kSizeNotGiven = -1;
  int size = kSizeNotGiven;  // cells per axis; not given: 64, or kFilamentDfgSize for Filament
  std::string out;
  int samples = analysis::kLutSamples;
  int threads = 0;                   // 0: every hardware thread
  std::string layout = "split-sum";  // dfg only
  // energy only: the dielectric table (E_F(μ, α, η), E_F,avg(α, η)) of `slices` η-slices (a
  // square number: the slices tile a square atlas) instead of the conductors' E and E_avg.
  bool dielectric = false;
  int slices = analysis::kDielectricSlices;
  bool half = false;     // textures as half floats (EXR HALF channels; .h: uint16_t bit patterns)
  bool headers = false;  // .exr output: each texture also as a C header beside it (FILE.h, ...)
  // .h output: the C symbol of the first texture's header (a texture after the first adds its
  // suffix, _2, _3, ...); empty: fresnel_lab_dfg, fresnel_lab_dfg_filament, fresnel_lab_ltc,
  // fresnel_lab_ltc_moments, fresnel_lab_energy or fresnel_lab_energy_dielectric.
  std::string symbol;
};

// Each checks the request first (InputError for a size, sample count, thread count, output type or
// symbol out of range, or a symbol without .h output), then computes the table. Wherever a table
// is written as textures, out.h writes the same textures as C headers (documents/c_header.h: one
// per texture, where the EXR files go, with the EXR's texels and attributes; C99 and C++).
// DFG in `request.layout`: out.exr (RGB; split-sum: the dfg texture, and each further texture of
// the table terms in STEM_2.exr, ...), out.csv (every channel), out.h (split-sum: out.h, STEM_2.h,
// ...; Filament: half-float bit patterns) or, Filament only, out.inc (Filament's dfg.inc form: the
// array's initializer list). Rows run from smooth to rough (GL order: the first row is texture v =
// 0), texels within a row from n·v = 0 to 1, at texel centres; uv = (n·v, perceptual roughness).
io::Output dfg_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// LTC moments: out.exr (RGB = n_D, f_D, l_D) and STEM_3.exr (the basis moments), out.h and
// STEM_3.h, or out.csv.
io::Output moments_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// LTC fit: out.exr gives FILE_1.exr (the inverse matrix), FILE_2.exr (n_D, f_D, l_D, sphere form
// factor), FILE_3.exr (the basis moments) and FILE.csv; out.h gives FILE_1.h, FILE_2.h, FILE_3.h;
// out.csv gives the CSV only.
io::Output ltc_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// Kulla–Conty's tables (analysis/lut/energy.h) on the DFG grid: out.exr or out.h (R = E(n·v,
// roughness), G = E_avg(roughness)), or out.csv.
io::Output energy_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// The dielectric table (analysis/lut/energy.h, dielectric_energy_table) on the DFG grid: out.exr or
// out.h, a square atlas of √K × √K tiles of N × N texels, slice k in tile (k mod √K, k div √K),
// RGBA = E_F(η_k), E_F,avg(η_k), E_F(1/η_k), E_F,avg(1/η_k); or out.csv (a row per slice and
// cell). energy_lut with request.dielectric calls it.
io::Output dielectric_energy_lut(const LutRequest& request,
                                 const analysis::LutProgress& progress = {});
// Filament's layout as texel values, 3 per texel in file order (the half floats are these rounded).
std::vector<float> filament_dfg_values(const analysis::DfgTable& table,
                                       const std::vector<double>& sheen);

// One line on the error as rendered of the tables `r` describes, under `lighting`, over the metals
// of `studies` (the catalog's): the tables' own error (analysis::table_error_summary).
std::string table_error_line(const analysis::Context& ctx,
                             const std::vector<analysis::MaterialStudy>& studies,
                             const LutRequest& r, analysis::Lighting lighting);

}  // namespace fl::jobs
