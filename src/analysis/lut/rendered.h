#pragma once
// Error as rendered: what an engine computes for a GGX lobe from a Fresnel model's parameters and
// the lookup tables (or the model at n·v where no table pre-integrates it), against brute-force
// integration of the lobe with the spectral Fresnel ground truth inside the integral.
//
// The engine reads the tables as `lut` writes them (by default 64², 32-bit floats), bilinearly, as
// a shader does: the DFG texture at (n·v, roughness) and the LTC moments at (roughness,
// √(1 − n·v)), both on endpoints (texel k holds k/(N − 1)). Only the texels a point reads are
// integrated (the same integrals as the full tables). The lobe's shape (the LTC matrix, the
// prefiltered environment) is the same for every Fresnel model and is not part of this error: it
// compares the Fresnel-weighted lobe integrals. The tables' own error is the engine's shading from
// the tables against the same shading from the exact integrals at the point.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "analysis/lut/lut.h"
#include "analysis/lut/truth_quadrature.h"
#include "analysis/pipeline/context.h"
#include "fresnel/model_spec.h"

namespace fl::analysis {

enum class Lighting { Punctual, Ibl, Area };
const char* lighting_name(Lighting l);                 // punctual | ibl | area
Lighting lighting_from_name(const std::string& name);  // InputError for anything else
const fresnel::LightingSupport& lighting_support(fresnel::Model m, Lighting l);

// The stated default roughness set (perceptual, α = roughness²) and the view angles of every
// shading grid.
inline constexpr std::array<double, 5> kDefaultRoughness{0.2, 0.4, 0.6, 0.8, 1.0};
inline constexpr std::array<double, 6> kShadingViewDeg{0.0, 30.0, 50.0, 65.0, 75.0, 85.0};
// The tables' size as an engine ships them (`lut --size` default).
constexpr int kEngineLutSize = 64;

// How a table's texels are stored: 32-bit floats, half floats (RGBA16F), or 16-bit unsigned
// normalized integers (Unreal Engine 4's G16R16 pre-integrated table).
enum class TexelStorage { Float, Half, Unorm16 };
const char* texel_storage_name(TexelStorage s);  // float | half | unorm16
// v as a texel of that storage holds it (half: the float rounded to the nearest half, ties to
// even, as OpenEXR and GPUs convert; unorm16: clamped to [0, 1], to the nearest k/65535).
double stored_texel(TexelStorage s, double v);

// The tables an engine reads: what the DFG and LTC-moment textures' texels hold, where they sit,
// and how they are stored.
struct EngineTables {
  LutGrid dfg, ltc;
  TexelStorage storage = TexelStorage::Float;
};
// The tables `lut` writes at `size` (dfg_grid, ltc_grid) in `storage`.
EngineTables engine_tables(int size = kEngineLutSize, TexelStorage storage = TexelStorage::Float);
// Roughness 0 is a mirror: the lobe is the reflection direction alone (v·h = n·v), so the truth is
// the spectral curve at n·v and every model renders as itself at n·v, with no table read.
struct ShadingPoint {
  double roughness = 0, view_deg = 0, nov = 0, alpha = 0;
  bool mirror = false;  // roughness 0
  // The lobe's weight on each node of the truth curve (truth_nodes()): the kLutSamples
  // visible-normal samples' weights at their v·h, split among the nodes of the sample's panel as
  // the interpolating polynomial splits them (its Lagrange basis at v·h), over kLutSamples (a
  // mirror: none). The truth is linear in the curve, so Σ_k w_k·curve_k is the sampled integral.
  std::vector<double> truth_weights;
  DfgTexel dfg;    // the DFG texture read bilinearly here (a mirror: none)
  GgxMoments ltc;  // the LTC moments texture (n_D, f_D, l_D) read bilinearly here (a mirror: none)
  DfgTexel dfg_exact;    // the same integrals at this point's own n·v and α, not stored
  GgxMoments ltc_exact;  // likewise the moments
};
// Every roughness × kShadingViewDeg, the engine reading `tables`.
std::vector<ShadingPoint> shading_points(const std::vector<double>& roughness, int threads = 0,
                                         const EngineTables& tables = engine_tables());
// Points at given (n·v, roughness), view_deg = acos(n·v), the engine reading `tables`. With
// mirror_at_zero false, roughness 0 reads the tables like any other roughness (what a shader's
// _ibl and _area functions compute when called there; the truth is the lobe of α =
// ltc_alpha_at(0)) instead of being a mirror.
struct NovRoughness {
  double nov = 1, roughness = 0;
};
std::vector<ShadingPoint> shading_points_at(const std::vector<NovRoughness>& at,
                                            bool mirror_at_zero = true, int threads = 0,
                                            const EngineTables& tables = engine_tables());

// Where the engine's lobe integrals come from: the tables (as shipped), or the exact integrals at
// the point (what a table of infinite resolution and precision would give).
enum class Integrals { Tables, Exact };

// The lobe integral with the spectral ground truth per v·h, per point: Σ_k w_k·curve_k from the
// curve at the nodes the points weigh (a mirror: the curve at n·v).
std::vector<color::Rgb> lobe_truth(const Context& ctx, const LoadedMaterial& m,
                                   const std::vector<ShadingPoint>& points);

// What the engine computes at one point (Ibl or Area): a·n + b·f + c·l from the model's table terms
// where it is pre-integrated, else F(n·v)·(the lobe's Fresnel-free integral); at a mirror point
// the model at n·v.
color::Rgb engine_shading(fresnel::Model m, const std::vector<double>& params, Lighting lighting,
                          const ShadingPoint& p, Integrals integrals = Integrals::Tables);
// engine_shading at every point into out[0, points.size()), the model's table terms computed once.
void engine_shading(fresnel::Model m, const std::vector<double>& params, Lighting lighting,
                    std::span<const ShadingPoint> points, color::Rgb* out,
                    Integrals integrals = Integrals::Tables);

// What the engine computes at one point from each channel's weights on the tables' terms (a model's
// own, or a curve projected on the terms: fresnel/projection.h): Σ_t w_t·(the lobe's integral of
// term t) read from the tables.
color::Rgb engine_shading_terms(const std::array<fresnel::TableTerms, 3>& weights,
                                Lighting lighting, const ShadingPoint& p,
                                Integrals integrals = Integrals::Tables);
// ΔE2000 between truth and the engine's shading from table-term weights at every point.
std::vector<double> rendered_de00_terms(const Context& ctx, const std::vector<color::Rgb>& truth,
                                        const std::array<fresnel::TableTerms, 3>& weights,
                                        Lighting lighting, const std::vector<ShadingPoint>& points);
// The same with the truth in CIELAB (lab_curve of lobe_truth): a page's truth converted once for
// all its shaders and lightings.
std::vector<double> rendered_de00_terms(const Context& ctx,
                                        const std::vector<color::Lab>& truth_lab,
                                        const std::array<fresnel::TableTerms, 3>& weights,
                                        Lighting lighting, const std::vector<ShadingPoint>& points);

// How an engine evaluates a model's Fresnel term under IBL or area lights.
enum class EngineWay {
  Native,   // through its own table terms where it has them, else AtNdotV
  AtNdotV,  // F(n·v) × the lobe's Fresnel-free integral, whatever tables hold the model
  HoffmanSpan,  // its curve projected on {1, (1 − μ)⁵, μ(1 − μ)⁶}, pre-integrated by those terms
  BasisSpan,  // its curve projected on the 5-term basis, pre-integrated by the basis tables
};
// The terms a projecting way (HoffmanSpan, BasisSpan) projects on; empty for the others.
std::span<const fresnel::Term> projected_span(EngineWay w);

// The model's RGB curve at the context's angles (uniform in θ, as the basis models' own
// projection) projected on `terms`, per channel (fresnel/projection.h).
std::array<fresnel::TableTerms, 3> projected_weights(const Context& ctx, fresnel::Model m,
                                                     const std::vector<double>& params,
                                                     std::span<const fresnel::Term> terms);

// ΔE2000 between truth and engine at every point, the engine evaluating the model `way`.
std::vector<double> rendered_de00(const Context& ctx, const std::vector<color::Rgb>& truth,
                                  fresnel::Model m, const std::vector<double>& params,
                                  Lighting lighting, const std::vector<ShadingPoint>& points,
                                  EngineWay way = EngineWay::Native);
std::vector<double> rendered_de00(const Context& ctx, const std::vector<color::Lab>& truth_lab,
                                  fresnel::Model m, const std::vector<double>& params,
                                  Lighting lighting, const std::vector<ShadingPoint>& points,
                                  EngineWay way = EngineWay::Native);

// The tables' own error: ΔE2000 between the engine's shading of the model from the tables and from
// the exact integrals, at every point.
std::vector<double> table_de00(const Context& ctx, fresnel::Model m,
                               const std::vector<double>& params, Lighting lighting,
                               const std::vector<ShadingPoint>& points);

struct ErrorStats {
  double rms = 0, max = 0;
};
ErrorStats error_stats(const std::vector<double>& de00);

}  // namespace fl::analysis
