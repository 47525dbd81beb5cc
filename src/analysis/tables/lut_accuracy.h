#pragma once
// The lookup tables' accuracy as rendered: pre-integrated Fresnel against brute-force spectral
// integration of the GGX lobe.
#include <vector>

#include "analysis/pipeline/context.h"
#include "analysis/tables/table.h"

namespace fl::analysis {

// `table lut-accuracy`: per metal, pre-integrated Schlick (R0 n_D + (1 − R0) f_D) and F82
// (… − a l_D) shading against brute-force integration of the lobe with the spectral Fresnel
// ground truth, in ΔE2000, over a grid of roughness × view angle.
Table lut_accuracy_table(const Context& ctx, const std::vector<LoadedMaterial>& materials);

}  // namespace fl::analysis
