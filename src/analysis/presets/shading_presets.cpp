#include "analysis/presets/shading_presets.h"

#include <algorithm>
#include <cmath>

#include "color/lab.h"
#include "fresnel/exact.h"
#include "fresnel/media.h"

namespace fl::analysis {

// Sweeps of the coordinate descent; gold's linear Rec.709 F0 settles to 1e-4 ΔE2000 within 8.
constexpr int kUnitRangeSweeps = 16;

bool out_of_range(double v) {
  return v < -kOutOfRangeTolerance || v > 1.0 + kOutOfRangeTolerance;
}

void add_channels(NamedValues& out, const std::string& prefix, const color::Rgb& v) {
  const char* ch[] = {"r", "g", "b"};
  for (int c = 0; c < 3; ++c) out.emplace_back(prefix + "_" + ch[c], v[c]);
}

std::string out_of_range_list(const NamedValues& values) {
  std::string out;
  for (const auto& [name, v] : values)
    if (out_of_range(v)) out += (out.empty() ? "" : " ") + name;
  return out;
}

namespace {

bool is_clear(const LoadedMaterial& m) {
  return std::all_of(m.ior.ior.begin(), m.ior.ior.end(),
                     [](const auto& n) { return n.imag() <= kClearKappa; });
}

// Kernel: the larger ΔE2000 of F0 and F82 of a grey dielectric of real index eta (Fresnel's
// equations, Born & Wolf §1.5.2) against the spectral values. Grey: RGB (v, v, v) is the
// working space's white scaled to luminance v.
double dielectric_form_de00(const Context& ctx, double eta, const color::Rgb& f0,
                            const color::Rgb& f82) {
  const double r0 = fresnel::fresnel_conductor(1.0, eta, 0.0);
  const double r82 = fresnel::fresnel_conductor(1.0 / 7.0, eta, 0.0);
  const auto de = [&](const color::Rgb& v, double grey) {
    return color::ciede2000<double>(ctx.rgb_to_lab(v),
                                    ctx.rgb_to_lab(color::Rgb{grey, grey, grey}));
  };
  return std::max(de(f0, r0), de(f82, r82));
}

}  // namespace

ShadingPreset shading_preset(const Context& ctx, const MaterialStudy& study) {
  ShadingPreset p;
  p.material = study.material;
  p.metal = study.material->material.material_class == spectral::MaterialClass::Metal;
  p.clear = !p.metal && is_clear(*study.material);
  p.f0 = study.derived.f0;
  p.f82_tint = study.derived.f82_tint;
  p.edge_tint = study.derived.g_refl_eta;
  if (p.metal) return p;
  // RGB (1, 1, 1) is the space's white with Y = 1, so Y of a colour is the middle row of RGB → XYZ.
  const double f0_y = (ctx.space().rgb_to_xyz * p.f0).Y;
  p.ior = fresnel::ior_from_f0(f0_y);
  if (p.clear) return p;
  p.dielectric_form_de00 = dielectric_form_de00(ctx, p.ior, p.f0, study.derived.f82);
  p.metal_form = p.dielectric_form_de00 > kDielectricFormMaxDe00;
  p.metal = p.metal_form;
  return p;
}

OpenPbrParameters open_pbr_parameters(const ShadingPreset& p) {
  OpenPbrParameters o;
  if (p.metal) {
    o.base_metalness = 1;
    o.base_color = p.f0;
    o.specular_color = p.f82_tint;
  } else {
    o.specular_ior = p.ior;
    o.transmission_weight = p.clear ? 1 : 0;
    o.base_weight = p.clear ? 1 : 0;
  }
  return o;
}

UnitRangeColor into_unit_range(const Context& ctx, const color::Rgb& v,
                               const color::Mat3* to_working) {
  auto lab = [&](const color::Rgb& c) {
    return ctx.rgb_to_lab(to_working ? color::transform_rgb(*to_working, c) : c);
  };
  const color::Lab target = lab(v);
  auto cost = [&](const color::Rgb& c) { return color::ciede2000<double>(target, lab(c)); };
  UnitRangeColor out;
  const double scale = std::max({v.r, v.g, v.b, 1.0});
  for (int c = 0; c < 3; ++c) out.value[c] = std::clamp(v[c] / scale, 0.0, 1.0);
  // Coordinate descent: each channel in turn by golden-section search over [0, 1].
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int sweep = 0; sweep < kUnitRangeSweeps; ++sweep)
    for (int c = 0; c < 3; ++c) {
      double a = 0.0, b = 1.0;
      auto at = [&](double x) {
        color::Rgb t = out.value;
        t[c] = x;
        return cost(t);
      };
      for (int it = 0; it < 40; ++it) {
        const double x1 = b - phi * (b - a), x2 = a + phi * (b - a);
        if (at(x1) < at(x2))
          b = x2;
        else
          a = x1;
      }
      const double x = 0.5 * (a + b);
      if (at(x) < cost(out.value)) out.value[c] = x;
    }
  out.de00 = cost(out.value);
  return out;
}

}  // namespace fl::analysis
