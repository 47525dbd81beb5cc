#pragma once
// The talk's arguments for linear models, made measurable: parameter blending, gamut
// conversion, external media and internal reflection.
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

struct BlendOptions {
  double weight = 0.5;  // share of the second material
  int chain = 2;        // materials per blend: 2 = pairs; N > 2 blends N consecutive metals in turn
};

// Per pair (or chain) of metals: case A blends the evaluated curves, case B blends the parameters
// and evaluates once; RMS ΔE2000 between them. `blend` is Gulbrandsen (F0, g) with the
// "Refl. F0 + Refl. η" parameters (the stable CSV columns), largest first; `blend_models` adds
// every model (derived parameters).
Table blend_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                  const BlendOptions& o);
Table blend_models_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                         const BlendOptions& o);

// Parameters derived in the working space; case A evaluates there and converts the result, case B
// converts the parameters and evaluates in the target (lin_rec709, aces2065-1), through OCIO's
// matrices; ΔE2000 in the target space. `gamut` is Gulbrandsen (the stable CSV columns),
// `gamut_models` every model, with the number of converted channels that left the model's domain.
Table gamut_table(const Context& ctx, const std::vector<MaterialStudy>& studies);
Table gamut_models_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

// Every catalog material immersed in media of index 1.0 … 2.417: exact spectral Fresnel with
// the medium's index against Schlick with F0 adjusted by the symmetric formula
// (docs/conventions.md) and, for metals, an asymmetric metal variant; dielectrics also in a medium
// of their own index.
Table media_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

// Dielectrics seen from inside: exact internal reflection (relative index 1/n(λ), total internal
// reflection included) against Schlick evaluated with the transmission angle's cosine.
Table internal_table(const Context& ctx, const std::vector<MaterialStudy>& studies);

}  // namespace fl::analysis
