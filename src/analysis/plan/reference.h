#pragma once
// Reference values for testing an engine's port of the shaders: per shading point, what the
// shipped function returns from the shipped tables (the CPU engine model, analysis/lut/rendered.h),
// the spectral truth there and their ΔE2000.
//
// Points: under punctual lights the model at cos θ = n·v; under ibl and area the function
// fresnel_NAME_ibl / _area at (n·v, perceptual roughness), the roughness values given plus the
// tables' edges 0 and 1 (roughness 0 read from the tables as the function reads it, not as a
// mirror), n·v at the shading view angles (analysis/lut/rendered.h kShadingViewDeg) plus the edge
// kReferenceMinNov. A material whose every roughness is 0 is a mirror: its rows are the model at
// n·v (the function an engine calls for it), under each lighting.
#include <vector>

#include "analysis/plan/plan.h"
#include "util/table.h"

namespace fl::analysis {

// The decimals `plan --out` writes parameters with (materials.json); the reference rows are
// computed from the parameters as written.
constexpr int kPlanParamDecimals = 6;
// The grazing edge of the n·v axis: the lobe integrals vanish at n·v = 0 itself.
constexpr double kReferenceMinNov = 1e-3;

struct ReferenceMaterial {
  const LoadedMaterial* material = nullptr;
  fresnel::Model model{};
  std::vector<double> params;
  std::vector<double> roughness;
  bool mirror = false;
};

// The rows of each material under each lighting: material, model, parameters ("f0_r=0.955 …",
// each rounded to kPlanParamDecimals, the values the rows are computed with), lighting, function,
// nov, roughness (empty for punctual lights and mirrors), engine_r/g/b, truth_r/g/b, de00.
// The engine reads `tables`.
Table reference_table(const Context& ctx, const std::vector<ReferenceMaterial>& materials,
                      const std::vector<Lighting>& lightings, const EngineTables& tables);

// The plan's chosen option: each material with its model and parameters (as materials.json writes
// them), the engine reading the plan's tables (their size and storage); studies[k] is the scene's
// material k.
Table plan_reference(const Context& ctx, const std::vector<MaterialStudy>& studies, const Plan& p);

// `shader MODEL --reference MATERIAL...`: the model's derived parameters for each material under
// one lighting, at `roughness` (empty: kDefaultRoughness), the engine reading `tables`.
Table model_reference(const Context& ctx, const std::vector<LoadedMaterial>& materials,
                      fresnel::Model model, Lighting lighting, std::vector<double> roughness,
                      const EngineTables& tables);

}  // namespace fl::analysis
