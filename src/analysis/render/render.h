#pragma once
// A sphere shaded with the GGX specular lobe (brdf/ggx.h) and chosen Fresnel terms, lit by the
// analytic environment or a latitude-longitude environment map. Pure functions; no I/O.
//
// Scene (world frame: y up, +z toward the camera). Orthographic camera looking along −z at a
// unit sphere at the origin; the image spans [−1.1, 1.1]² so the sphere fills 1/1.1 of it. With an
// odd image size the centre pixel's sample point is exactly (0, 0): normal = view = +z.
//
// Analytic environment (radiance in working-space RGB, documented in default_environment()):
//   studio: for directions above the horizon, horizon colour → zenith colour as √(d.y);
//   ground: below the horizon, horizon/2 → ground colour within 7° of the horizon, then constant;
//   key light: a disc of uniform radiance and half-angle δ around key_direction, replacing the sky
//   inside it. key_direction is tilted by less than δ from +z, so the mirror reflection of the
//   view ray at the sphere's centre (straight back along +z) lands in the key light: a mirror
//   sphere's centre pixel is exactly F(cos 0) · key_radiance = F0 · key_radiance.
//
// Environment map (EnvironmentMap): an equirectangular image of working-space radiance, oriented as
// OpenEXR's latitude-longitude maps (ImfEnvmap.h): latitude +π/2 (+y) at the top row, longitude +π
// at the left edge falling to −π at the right, longitude 0 along +z and +π/2 along +x. Direction
// d ↔ image (u, v) ∈ [0, 1]²: v = θ/π with θ = arccos(d.y), u = ½ − (λ − ρ)/2π (mod 1) with
// longitude λ = atan2(d.x, d.z) and ρ a rotation about the vertical axis; pixel (x, y) covers
// [x, x + 1)/width × [y, y + 1)/height. With ρ = 0 the image centre (+z, behind the camera) is
// reflected at the sphere's centre and the image's left and right edges (−z) at its rim.
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "analysis/pipeline/context.h"
#include "brdf/ggx.h"
#include "color/values.h"
#include "fresnel/registered_models.h"
#include "io/environment_image.h"

namespace fl::analysis {

struct Environment {
  color::Rgb zenith, horizon, ground;
  brdf::Vec3 key_direction;  // unit, world frame
  double key_half_angle_deg = 0;
  color::Rgb key_radiance;
};

// A neutral studio: every radiance a multiple of the working space's white (1, 1, 1), so that
// the environment lends no colour of its own and metals show theirs (silver warmer than aluminium,
// gold yellow above the horizon as below). An overhead softbox gradient, zenith 0.80, falling to
// 0.40 at the horizon; a dark grey floor 0.05; a key light of radiance 1 and half-angle 18° around
// normalize(−0.15, 0.20, 1) (14.0° up-left of the view axis).
Environment default_environment();

// Fresnel Lab's own analytic environment (described above): radiance arriving from world direction
// `dir` (unit).
color::Rgb environment_radiance(const Environment& env, const brdf::Vec3& dir);

// Radiance looked up bilinearly between pixel centres (wrapping in u, clamped at the poles) and
// directions drawn in proportion to each pixel's luminance × sin θ (the pixel's solid angle), so
// bright sources such as the sun are found with few samples (Pharr, Jakob & Humphreys, PBRT 3rd
// ed. §14.2.4: piecewise-constant 2D sampling of an infinite area light).
class EnvironmentMap {
 public:
  // `luminance` weighs R, G, B into the sampling density (the working space's Y row; negative
  // pixel values count as 0). Throws std::invalid_argument for an empty or inconsistent image.
  EnvironmentMap(io::LatLongImage image, const color::Rgb& luminance, double rotation_deg = 0);

  color::Rgb radiance(const brdf::Vec3& dir) const;
  // False when the image is black: then no direction can be drawn.
  bool can_sample() const { return total_ > 0; }
  // A direction drawn with density pdf(direction) per steradian from two uniform numbers in [0, 1).
  brdf::Vec3 sample(double u1, double u2, double& pdf) const;
  double pdf(const brdf::Vec3& dir) const;
  // radiance(dir) and pdf(dir) together (one direction → (u, v) conversion).
  void lookup(const brdf::Vec3& dir, color::Rgb& radiance, double& pdf) const;

  const io::LatLongImage& image() const { return image_; }
  double rotation_deg() const { return rotation_deg_; }
  // (u, v) of a unit direction and back (the mapping above).
  void direction_to_uv(const brdf::Vec3& dir, double& u, double& v) const;
  brdf::Vec3 uv_to_direction(double u, double v) const;

 private:
  color::Rgb texel(int x, int y) const;
  color::Rgb radiance_uv(double u, double v) const;
  double pdf_uv(double u, double v, double sin_theta) const;
  io::LatLongImage image_;
  double rotation_deg_ = 0;
  std::vector<double> row_cdf_;     // height + 1 entries, 0 … 1
  std::vector<double> column_cdf_;  // per row, width + 1 entries, 0 … 1
  std::vector<double> weight_;      // per pixel: luminance × sin θ
  double total_ = 0;                // Σ weight
};

// What lights the sphere.
using SceneLight = std::variant<Environment, EnvironmentMap>;

// A Fresnel reflectance tabulated uniformly in cosθ ∈ [0, 1] (entry i at cosθ = i/(n − 1)),
// looked up with linear interpolation; entries 0 and n − 1 are exactly F(90°) and F(0°).
struct FresnelTable {
  std::vector<color::Rgb> values;
  color::Rgb at(double cos_theta) const;
};
FresnelTable tabulate_fresnel(const std::function<color::Rgb(double)>& fresnel, int entries = 1025);
// Spectral ground truth (ground_truth_rgb) and a model with its flat parameter vector.
FresnelTable truth_fresnel_table(const Context& ctx, const spectral::ComplexIorSpectrum& ior,
                                 double eta_outside);
FresnelTable model_fresnel_table(fresnel::Model model, const std::vector<double>& params);

// Below this GGX α (roughness 0.01) the lobe is treated as a perfect mirror.
constexpr double kMirrorAlpha = 1e-4;

// Veach 1997 (multiple importance sampling, balance heuristic) with Heitz 2018 (GGX VNDF sampling):
// outgoing radiance toward the view direction v at a surface point with normal n (both unit, world
// frame), for the GGX lobe of width alpha = roughness² with Fresnel F(v·h). Mirror: F(n·v) ·
// L(reflect(v, n)). Otherwise `samples` VNDF directions and `samples` directions drawn from the
// lighting (the analytic key light's cone, uniform in solid angle; or the environment map's
// density), both from the same Hammersley set, so the result is deterministic (a fixed set per
// pixel: the quasi-Monte Carlo error is smooth across the image, not noise). One set of directions
// shades every table in `fresnel`: out[i] is the shading with fresnel[i].
void shade_specular(const SceneLight& light, const std::vector<const FresnelTable*>& fresnel,
                    const brdf::Vec3& n, const brdf::Vec3& v, double alpha, int samples,
                    color::Rgb* out);
color::Rgb shade_specular(const SceneLight& light, const FresnelTable& fresnel, const brdf::Vec3& n,
                          const brdf::Vec3& v, double alpha, int samples);

struct RenderSettings {
  int size_px = 255;        // width = height; odd keeps a pixel centred on the sphere's centre
  double roughness = 0.25;  // perceptual; α = roughness²
  int samples = 64;         // per strategy and shading point
  int threads = 0;          // 0: hardware concurrency
  // (rows done, rows in all) after each finished row of pixels, from any thread, one call at a
  // time; empty: no report.
  std::function<void(int, int)> progress;
};

// Premultiplied linear RGB plus coverage; pixels at the silhouette average 4×4 sub-samples.
struct SphereImage {
  int width = 0, height = 0;
  std::vector<float> rgb;    // 3 per pixel, row y = 0 at the top
  std::vector<float> alpha;  // coverage
};
// One image per table, all shaded with the same directions (shade_specular).
std::vector<SphereImage> render_spheres(const SceneLight& light,
                                        const std::vector<const FresnelTable*>& fresnel,
                                        const RenderSettings& settings);
SphereImage render_sphere(const SceneLight& light, const FresnelTable& fresnel,
                          const RenderSettings& settings);

// A working-space environment map from an image in colour space `space` (a name the context's
// SpaceLibrary knows), converted with OpenColorIO's matrix from `space` to the working space, then
// exposed: scaled so that its mean luminance over the sphere of directions (solid-angle weighted)
// is 2^exposure_ev. At 0 EV a white Lambertian sphere lit by it has mean luminance 1 (the working
// space's white, Y = 1, the reference of CIELAB and so of the heat maps), as a look-dev artist
// exposes a plate so that an 18% grey ball reads 0.18; ΔE2000 then compares across environments.
// `scale` receives the factor applied. An image whose mean luminance is not positive and finite
// (black, all negative, overflowing) is an InputError: no exposure can light it.
EnvironmentMap environment_map(const Context& ctx, io::LatLongImage image, const std::string& space,
                               double rotation_deg, double exposure_ev, double& scale);

// ΔE2000 over the covered pixels of a heat map: mean and max, and the mean in bands of the angle θ
// between the surface normal and the view (0–30°, 30–60°, 60–80°, 80–90°): where on the sphere
// (centre to rim) a model departs from the truth.
struct HeatmapStats {
  double mean = 0, max = 0;
  long long pixels = 0;
  std::vector<double> band_upper_deg{30, 60, 80, 90};
  std::vector<double> band_mean;  // per band; NaN for a band without pixels
};
HeatmapStats heatmap_stats(const std::vector<double>& de2000, int width, int height);

// A model's render of a material and its ΔE2000 heat map against the truth.
struct ModelRender {
  fresnel::Model model;
  std::vector<double> params;  // the model's parameters
  SphereImage image;
  std::vector<double> de2000;  // per pixel, truth against the model (NaN: no surface)
  HeatmapStats stats;
};

// Spheres under `light`, all in one pass: the spectral ground truth first, then each model with its
// parameter set (params[i] for models[i]).
std::vector<SphereImage> render_truth_and_models(const Context& ctx, const LoadedMaterial& m,
                                                 const SceneLight& light,
                                                 const std::vector<fresnel::Model>& models,
                                                 const std::vector<std::vector<double>>& params,
                                                 const RenderSettings& settings);

// A material's sphere under `light` with the spectral ground truth and with each model's derived or
// fitted parameters (`kind`, from the material's study), all in one pass.
struct MaterialRender {
  SphereImage truth;
  std::vector<ModelRender> models;
};
MaterialRender render_material(const Context& ctx, const LoadedMaterial& m, const SceneLight& light,
                               const std::vector<fresnel::Model>& models, const std::string& kind,
                               const RenderSettings& settings);

// Per pixel ΔE2000 between two renders of the same scene (un-premultiplied colours taken as
// working-space RGB, CIELAB relative to the space's white at Y = 1); NaN where alpha is 0.
std::vector<double> de2000_image(const Context& ctx, const SphereImage& a, const SphereImage& b);

}  // namespace fl::analysis
