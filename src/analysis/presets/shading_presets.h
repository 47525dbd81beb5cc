#pragma once
// Presets for renderers' shading models (OpenPBR, Autodesk Standard Surface, glTF 2.0, MaterialX's
// generalized Schlick BSDF), and the out-of-range policy every exported value follows.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"

namespace fl::analysis {

// Out-of-range policy (one for every format). A reflectance-like value (F0, F82, the F82 tint,
// Gulbrandsen's g, a base or specular colour) below 0 or above 1 by more than kOutOfRangeTolerance
// is flagged, by name, in the out_of_range column (CSV, Markdown, JSON) or attribute (MaterialX
// doc, glTF extras). The tables are data and keep the spectral value unclamped; every colour a
// renderer reads (MaterialX inputs, glTF factors) is stored in [0, 1], as into_unit_range(), with
// the true value and the ΔE2000 the stored colour costs beside it. The tolerance is rounding noise:
// Gulbrandsen's g of a lossless dielectric is 0 analytically and comes out of the spectral
// quadrature within 2e-5 of it.
inline constexpr double kOutOfRangeTolerance = 1e-4;
bool out_of_range(double v);

// Named values, checked together: the names of those out of range, space-separated ("" if none).
using NamedValues = std::vector<std::pair<std::string, double>>;
void add_channels(NamedValues& out, const std::string& prefix,
                  const color::Rgb& v);  // prefix_r, _g, _b
std::string out_of_range_list(const NamedValues& values);

// A dielectric is clear (transmissive in the exports) when κ ≤ kClearKappa at every wavelength of
// the grid: an absorption length λ/(4πκ) of at least 0.3 mm at 360 nm. Otherwise it is opaque:
// specular reflection only, no diffuse base (the data says nothing of scattering under the
// surface).
inline constexpr double kClearKappa = 1e-4;

// Representation. A metal by the data is exported as a metal. A clear dielectric as a dielectric
// (its transmission matters). An opaque dielectric (an absorbing semiconductor: Si, Ge, GaAs) is
// exported as a dielectric only when a dielectric of one real index reproduces its spectral F0 and
// F82 within kDielectricFormMaxDe00 (the larger of the two ΔE2000); otherwise as a metal, whose F0
// (base colour) and F82 tint reproduce both exactly and keep F0's hue.
inline constexpr double kDielectricFormMaxDe00 = 1.0;

struct ShadingPreset {
  const LoadedMaterial* material = nullptr;
  bool metal = false, clear = false;
  bool metal_form = false;  // exported as a metal although the data is a dielectric
  // The larger of the F0 and F82 ΔE2000 of the one-index dielectric form against the spectral
  // values (opaque dielectrics; NaN otherwise).
  double dielectric_form_de00 = NAN;
  color::Rgb f0, f82_tint, edge_tint;  // edge tint: Gulbrandsen's g from (F0, Refl. η)
  // Dielectrics: the real index (relative to the outside medium) whose normal-incidence
  // reflectance ((η − 1)/(η + 1))² is the luminance Y of F0, so a renderer's scalar IOR reflects
  // as much light head-on as the spectral F0.
  double ior = 1.5;
};
ShadingPreset shading_preset(const Context& ctx, const MaterialStudy& study);

// What renderer documents (MaterialX, glTF) are written with: the perceptual roughness r of every
// material (α = r²; OpenPBR's and Standard Surface's specular_roughness, glTF's roughnessFactor,
// the generalized Schlick BSDF's roughness α = r²), and the materials a glob skipped with why.
inline constexpr double kDefaultExportRoughness = 0.3;
struct ExportOptions {
  double roughness = kDefaultExportRoughness;
  std::vector<std::string> skipped;  // "SPEC: reason", one per skipped material
};

// OpenPBR Surface (v1.1): metals base_metalness 1, base_color F0, specular_color the F82 tint;
// dielectrics base_metalness 0, specular_ior η, specular_color white, transmission_weight 1 when
// clear, base_weight 0 when opaque. Unused inputs keep OpenPBR's defaults (base_color 0.8,
// specular_ior 1.5).
struct OpenPbrParameters {
  color::Rgb base_color{0.8, 0.8, 0.8}, specular_color{1, 1, 1};
  double base_weight = 1, base_metalness = 0, specular_ior = 1.5, transmission_weight = 0;
};
OpenPbrParameters open_pbr_parameters(const ShadingPreset& p);

// A colour stored where only [0, 1] fits (glTF factors): the colour of [0, 1]³ nearest to `v` in
// ΔE2000 (the working space's CIELAB), found by coordinate descent from `v` scaled down to a
// largest channel of 1; and that ΔE2000. For gold's linear Rec.709 F0 (1.038, 0.728, 0.365) it
// costs 0.76, against 0.83 for the scaled colour and 1.26 for clipping each channel.
struct UnitRangeColor {
  color::Rgb value;
  double de00 = 0;
};
// `to_working` given, v is in another RGB space (a document's) and the matrix takes it to the
// working space, where the ΔE2000 is measured.
UnitRangeColor into_unit_range(const Context& ctx, const color::Rgb& v,
                               const color::Mat3* to_working = nullptr);

}  // namespace fl::analysis
