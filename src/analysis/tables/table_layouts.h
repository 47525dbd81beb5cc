#pragma once
// Lookup-table layouts on one metric: the tables' own error (the engine's shading from the DFG
// table against the same shading from the exact integrals at each shading point, under IBL) for
// every layout an engine ships: ours at several sizes, texel centres against endpoints, half
// against float; Filament's cmgen table; Unreal Engine 4's 128×32 pre-integrated table.
#include <string>
#include <vector>

#include "analysis/lut/rendered.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

struct TableLayout {
  std::string name;    // "ours, endpoints", "Filament cmgen", ...
  std::string source;  // where the layout is defined
  EngineTables tables;
  bool schlick_only = false;  // holds Schlick's scale and bias only (no further term channels)
};
// The layouts compared, ours first.
std::vector<TableLayout> table_layouts();

// Filament's cmgen DFG table (libs/ibl CubemapIBL.cpp, DFG): n·v on texel centres, (i + ½)/N;
// image row y holds roughness saturate((N − y + ½)/N), stored bottom row first, so the texel read
// at v = (j + ½)/N holds roughness min(1, (j + 1.5)/N): exact at roughness 1, one texel off
// below; RGB16F.
LutGrid cmgen_dfg_grid(int size);
// Unreal Engine 4's pre-integrated GF table (SystemTextures.cpp): 128 texels of n·v by 32 of
// roughness on texel centres, α = roughness², 16-bit unsigned normalized (G16R16).
LutGrid ue4_dfg_grid();

// The tables' own error of `tables` under `lighting` over the metals of `studies`: per metal the
// RMS over lut-accuracy's shading points; the median of Schlick's and of basis4's (derived), and
// basis4's largest.
struct TableErrorSummary {
  int metals = 0;
  double schlick_median = 0, basis4_median = 0, basis4_max = 0;
};
TableErrorSummary table_error_summary(const Context& ctx, const std::vector<MaterialStudy>& studies,
                                      const EngineTables& tables, Lighting lighting);

// `table lut-layouts`: per layout, the median and largest tables' own RMS ΔE2000 of Schlick and
// basis4 (derived) over the metals of `studies`.
Table table_layouts_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

}  // namespace fl::analysis
