#pragma once
// The exact conductor Fresnel equations as a shader helper (GLSL, translated to HLSL by the
// emitter) for the units whose kernel calls fresnel_conductor (exact.h).
#include "fresnel/model_spec.h"

namespace fl::fresnel {

// Born & Wolf, Principles of Optics §14.2, in the a/b form of exact.h, per channel, branch-free and
// without cancellation: with t0 = η² − κ² − sin²θ, t⁺ = max(t0, 0) and a² + b² = √(t0² + 4η²κ²),
// a² = (a² + b² + t0)/2 = (t⁺(t⁺ + a² + b²) + 2η²κ²)/(a² + b² + |t0|) (every term non-negative),
// so float keeps its precision for κ > η (silver, gold) and η < 1. |t0| is written max(t0, −t0).
// The 1e-30 floors only keep 0/0 (an index-matched interface) finite.
inline constexpr ShaderHelper kConductorShader{
    "fl_fresnel_conductor", R"(vec3 fl_fresnel_conductor(float cos_theta, vec3 eta, vec3 kappa) {
  float c = clamp(cos_theta, 0.0, 1.0);
  float c2 = c * c;
  float s2 = 1.0 - c2;
  vec3 eta2 = eta * eta;
  vec3 ek2 = eta2 * kappa * kappa;
  vec3 t0 = eta2 - kappa * kappa - s2;
  vec3 a2pb2 = sqrt(t0 * t0 + 4.0 * ek2);
  vec3 tp = max(t0, 0.0);
  vec3 a = sqrt((tp * (tp + a2pb2) + 2.0 * ek2) / max(a2pb2 + max(t0, -t0), 1e-30));
  vec3 t1 = a2pb2 + c2;
  vec3 t2 = 2.0 * a * c;
  vec3 rs = (t1 - t2) / max(t1 + t2, 1e-30);
  vec3 t3 = a2pb2 * c2 + s2 * s2;
  vec3 t4 = t2 * s2;
  vec3 rp = rs * (t3 - t4) / max(t3 + t4, 1e-30);
  return 0.5 * (rs + rp);
}
)"};

inline constexpr const ShaderHelper* kConductorHelpers[] = {&kConductorShader};

}  // namespace fl::fresnel
