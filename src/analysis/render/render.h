#pragma once
// A sphere shaded with the GGX specular lobe (brdf/ggx.h) and a chosen Fresnel, lit by an analytic
// environment. Pure functions; no I/O.
//
// Scene (world frame: y up, +z toward the camera). Orthographic camera looking along −z at a
// unit sphere at the origin; the image spans [−1.1, 1.1]² so the sphere fills 1/1.1 of it. With an
// odd image size the centre pixel's sample point is exactly (0, 0): normal = view = +z.
//
// Environment (radiance in working-space RGB, documented in default_environment()):
//   sky: for directions above the horizon, horizon colour → zenith colour as √(d.y);
//   ground: below the horizon, horizon/2 → ground colour within 7° of the horizon, then constant;
//   key light: a disc of uniform radiance and half-angle δ around key_direction, replacing the sky
//   inside it. key_direction is tilted by less than δ from +z, so the mirror reflection of the
//   view ray at the sphere's centre (straight back along +z) lands in the key light: a mirror
//   sphere's centre pixel is exactly F(cos 0) · key_radiance = F0 · key_radiance.
#include <functional>
#include <string>
#include <vector>

#include "analysis/pipeline/context.h"
#include "brdf/ggx.h"
#include "color/types.h"
#include "fresnel/model_set.h"

namespace fl::analysis {

struct Environment {
  color::Rgb zenith, horizon, ground;
  brdf::Vec3 key_direction;  // unit, world frame
  double key_half_angle_deg = 0;
  color::Rgb key_radiance;
};

// zenith (0.15, 0.25, 0.55), horizon (0.60, 0.60, 0.60), ground (0.08, 0.07, 0.06); key light
// radiance (1, 1, 1) — the working space's white — of half-angle 18° around
// normalize(−0.15, 0.20, 1) (14.0° up-left of the view axis).
Environment default_environment();

// Fresnel Lab's own analytic environment (described above): radiance arriving from world direction `dir` (unit).
color::Rgb environment_radiance(const Environment& env, const brdf::Vec3& dir);

// A Fresnel reflectance tabulated uniformly in cosθ ∈ [0, 1] (entry i at cosθ = i/(n − 1)),
// looked up with linear interpolation; entries 0 and n − 1 are exactly F(90°) and F(0°).
struct FresnelTable {
  std::vector<color::Rgb> values;
  color::Rgb at(double cos_theta) const;
};
FresnelTable tabulate_fresnel(const std::function<color::Rgb(double)>& fresnel, int entries = 1025);
// Spectral ground truth (ground_truth_rgb) and a model with its flat parameter vector.
FresnelTable truth_fresnel_table(const Context& ctx, const spectral::ComplexIorSpectrum& ior, double eta_outside);
FresnelTable model_fresnel_table(fresnel::Model model, const std::vector<double>& params);

// Below this GGX α (roughness 0.01) the lobe is treated as a perfect mirror.
constexpr double kMirrorAlpha = 1e-4;

// Veach 1997 (multiple importance sampling, balance heuristic) with Heitz 2018 (GGX VNDF sampling):
// outgoing radiance toward the view direction v at a surface point with normal n (both unit, world
// frame), for the GGX lobe of width alpha = roughness² with Fresnel F(v·h). Mirror: F(n·v) ·
// L(reflect(v, n)). Otherwise `samples` VNDF directions and `samples` directions uniform in the key
// light's cone, both from the same Hammersley set, so the result is deterministic (a fixed set per
// pixel: the quasi-Monte Carlo error is smooth across the image, not noise).
color::Rgb shade_specular(const Environment& env, const FresnelTable& fresnel, const brdf::Vec3& n,
                          const brdf::Vec3& v, double alpha, int samples);

struct RenderSettings {
  int size_px = 255;        // width = height; odd keeps a pixel centred on the sphere's centre
  double roughness = 0.25;  // perceptual; α = roughness²
  int samples = 64;         // per strategy and shading point
  int threads = 0;          // 0: hardware concurrency
};

// Premultiplied linear RGB plus coverage; pixels at the silhouette average 4×4 sub-samples.
struct SphereImage {
  int width = 0, height = 0;
  std::vector<float> rgb;    // 3 per pixel, row y = 0 at the top
  std::vector<float> alpha;  // coverage
};
SphereImage render_sphere(const Environment& env, const FresnelTable& fresnel, const RenderSettings& settings);

// A material's sphere under default_environment() with the spectral ground truth and, given a model,
// with that model's derived or fitted parameters (`kind`, from the material's study).
struct MaterialRender {
  SphereImage truth;
  SphereImage shown;           // the model's render; the truth's without a model
  std::vector<double> params;  // the model's parameters (empty without a model)
  std::vector<double> de2000;  // per pixel, truth against the model (empty without a model)
};
MaterialRender render_material(const Context& ctx, const LoadedMaterial& m, const fresnel::ModelSpec* model,
                               const std::string& kind, const RenderSettings& settings);

// Per pixel ΔE2000 between two renders of the same scene (un-premultiplied colours taken as
// working-space RGB, CIELAB relative to the space's white at Y = 1); NaN where alpha is 0.
std::vector<double> de2000_image(const Context& ctx, const SphereImage& a, const SphereImage& b);

}  // namespace fl::analysis
