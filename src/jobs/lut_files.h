#pragma once
// `lut dfg | ltc-moments | ltc`: the pre-integrated GGX tables (analysis/lut.h) computed and
// written as EXR textures, CSV tables and C++ headers.
#include <string>
#include <vector>

#include "analysis/lut/lut.h"
#include "io/writer.h"

namespace fl::report {

// The layouts of `lut dfg`. split-sum: R = dfg1 (scale), G = dfg2 (bias), B = dfg_f82, read as
// E = F0·R + G (Schlick), E = F0·R + G − a·B (Hoffman's F82). filament: Filament's multiscatter
// table as its shaders read it, R = dfg2 = ∫ Fc ρ cos, G = dfg1 + dfg2 = ∫ ρ cos, B = the sheen
// albedo; E = mix(dfg.xxx, dfg.yyy, F0), energy compensation 1 + F0 (1/dfg.y − 1).
enum class DfgLayout { SplitSum, Filament };
DfgLayout dfg_layout_from_name(
    const std::string& name);  // split-sum | filament (InputError otherwise)
// Filament's DFG_LUT_SIZE: the table its engine compiles in (128 × 128 RGB16F).
inline constexpr int kFilamentDfgSize = 128;

struct LutRequest {
  int size = 0;  // cells per axis; 0: 64, or kFilamentDfgSize for the Filament layout
  std::string out;
  int samples = analysis::kLutSamples;
  int threads = 0;                   // 0: every hardware thread
  std::string layout = "split-sum";  // dfg only
};

// Each checks the request first (InputError for a size, sample count, thread count or output type
// out of range), then computes the table.
// DFG in `request.layout`: out.exr (RGB), out.csv, out.h (a C++ header: float for split-sum,
// half-float bit patterns for Filament) or, Filament only, out.inc (Filament's dfg.inc form: the
// array's initializer list). Rows run from smooth to rough (GL order: the first row is texture
// v = 0), texels within a row from n·v = 0 to 1, at texel centres; uv = (n·v, perceptual
// roughness).
Output dfg_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// LTC moments: out.exr (RGB = n_D, f_D, l_D) or out.csv.
Output moments_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// LTC fit: out.exr gives FILE_1.exr (the inverse matrix), FILE_2.exr (n_D, f_D, l_D, sphere form
// factor) and FILE.csv; out.csv gives the CSV only.
Output ltc_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// Kulla–Conty's tables (analysis/lut/energy.h) on the DFG grid: out.exr (R = E(n·v, roughness),
// G = E_avg(roughness)), out.csv or out.h (kEnergyLut and kEnergyAverage).
Output energy_lut(const LutRequest& request, const analysis::LutProgress& progress = {});

// The C++ header of a split-sum DFG table: constexpr float kDfgLut[size * size * 3].
std::string dfg_header(const analysis::DfgTable& table);
// Filament's layout as texel values, 3 per texel in file order (the half floats are these rounded).
std::vector<float> filament_dfg_values(const analysis::DfgTable& table,
                                       const std::vector<double>& sheen);

}  // namespace fl::report
