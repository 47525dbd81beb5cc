#include "analysis/tables/media_tables.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/study/table_notes.h"
#include "color/ciede2000_batch.h"
#include "fresnel/exact.h"
#include "fresnel/media.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"

namespace fl::analysis {

namespace {

struct Medium {
  const char* name;
  double eta;
};
const std::vector<Medium>& media() {
  static const std::vector<Medium> m{{"air", 1.0},      {"water", 1.333}, {"1.6", 1.6},
                                     {"1.8", 1.8},      {"2.0", 2.0},     {"2.2", 2.2},
                                     {"diamond", 2.417}};
  return m;
}

double max_channel(const std::vector<color::Rgb>& curve) {
  double max_r = 0;
  for (const auto& v : curve) max_r = std::max({max_r, v.r, v.g, v.b});
  return max_r;
}

// One study's rows of the media table: every medium, and for a dielectric its own index. Returns
// the own-index row's largest exact reflectance (0 for a metal).
double add_media_rows(const Context& ctx, const MaterialStudy& s, Table& t) {
  const auto& m = *s.material;
  const color::Rgb f0_air = s.derived.f0;
  for (const auto& md : media()) {
    const auto truth = ground_truth_curve(ctx, m.ior, md.eta);
    color::Rgb sym, metal;
    for (int c = 0; c < 3; ++c) {
      sym[c] = fresnel::f0_in_medium_symmetric(f0_air[c], md.eta);
      metal[c] = fresnel::f0_in_medium_metal(f0_air[c], md.eta);
    }
    const double e_sym = curve_error(ctx, truth, schlick_curve(ctx, sym)).rms;
    const double e_metal =
        s.is_metal() ? curve_error(ctx, truth, schlick_curve(ctx, metal)).rms : std::nan("");
    t.rows.push_back({m.material.name, std::string(spectral::to_string(m.material.material_class)),
                      std::string(md.name), md.eta, e_sym, e_metal, max_channel(truth)});
    add_coverage_cells(t.rows.back(), m);
  }
  if (s.is_metal()) return 0;
  // In a medium of the material's own index the relative index is 1: the interface vanishes.
  spectral::ComplexIorSpectrum relative = m.ior;
  for (auto& v : relative.ior) v = {1.0, 0.0};
  const auto truth = ground_truth_curve(ctx, relative, 1.0);
  const double e_sym = curve_error(ctx, truth, schlick_curve(ctx, {0, 0, 0})).rms;
  t.rows.push_back({m.material.name, std::string("dielectric"), std::string("own index"),
                    std::nan(""), e_sym, std::nan(""), max_channel(truth)});
  add_coverage_cells(t.rows.back(), m);
  return max_channel(truth);
}

std::vector<std::string> media_notes(const std::vector<MaterialStudy>& studies) {
  return {
      "symmetric: √F0′ = (√F0 − √F0E)/(1 − √F0·√F0E) with √F0E = (η_E − 1)/(η_E + 1), per channel, "
      "from the "
      "F0 in air (docs/conventions.md, external media).",
      "metal_variant: treats the metal as real index 1 with κ² = 4F0/(1 − F0): F0′ = ((1 − η_E)²(1 "
      "− F0) + 4F0) / "
      "((1 + η_E)²(1 − F0) + 4F0). The talk's own asymmetric variant could not be recovered from "
      "the sources "
      "available here; this one is derived and measured instead.",
      "exact: the spectral Fresnel equations with the index relative to the medium, (n + iκ)/η_E "
      "per "
      "wavelength; exact_max_reflectance is the largest RGB channel over all angles.",
      "own index: the medium has the material's own complex index, so the relative index is "
      "exactly 1 at every "
      "wavelength: no interface, no reflection; Schlick with F0′ = 0 still rises towards grazing.",
      coverage_note(materials_of(studies))};
}

// One dielectric seen from inside: its row of the internal table.
std::vector<Cell> internal_row(const Context& ctx, const MaterialStudy& s) {
  const auto& m = *s.material;
  // Seen from inside: the outside medium is the material, the far side has index 1.
  spectral::ComplexIorSpectrum inverse = m.ior;
  double n_min = 1e300;
  for (auto& v : inverse.ior) {
    n_min = std::min(n_min, v.real());
    v = {1.0 / v.real(), 0.0};
  }
  std::vector<color::Rgb> truth, approx;
  const color::Rgb f0 = s.derived.f0;
  for (double c : ctx.cos_thetas()) {
    truth.push_back(ground_truth_rgb(ctx, inverse, c, 1.0));
    approx.push_back({fresnel::schlick_internal(c, f0.r), fresnel::schlick_internal(c, f0.g),
                      fresnel::schlick_internal(c, f0.b)});
  }
  const auto e = curve_error(ctx, truth, approx);
  const auto de = de2000_per_angle(ctx, truth, approx);
  // Past the largest critical angle, asin(1/n) for the smallest n of any wavelength or channel,
  // everything is totally reflected.
  for (int ch = 0; ch < 3; ++ch) n_min = std::min(n_min, fresnel::ior_from_f0(f0[ch]));
  const double crit_cos = std::sqrt(1.0 - 1.0 / (n_min * n_min));
  const double c_beyond = crit_cos * (1.0 - 1e-9);
  const auto exact_c = ground_truth_rgb(ctx, inverse, c_beyond, 1.0);
  const double schlick_c = std::min({fresnel::schlick_internal(c_beyond, f0.r),
                                     fresnel::schlick_internal(c_beyond, f0.g),
                                     fresnel::schlick_internal(c_beyond, f0.b)});
  std::vector<Cell> row{
      m.material.name, std::acos(crit_cos) * 180.0 / std::numbers::pi, e.rms,    e.mean, e.max,
      de.front(),      std::min({exact_c.r, exact_c.g, exact_c.b}),    schlick_c};
  add_coverage_cells(row, m);
  return row;
}

}  // namespace

Table media_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  Table t;
  t.name = "media";
  t.title =
      "External media: exact spectral Fresnel against Schlick with an adjusted F0 (RMS ΔE2000)";
  t.columns = {{"material"},
               {"class"},
               {"medium"},
               {"eta_medium", 3},
               {"symmetric", 3},
               {"metal_variant", 3},
               {"exact_max_reflectance", 6}};
  add_coverage_columns(t);
  double own_max = 0;
  for (const auto& s : studies) own_max = std::max(own_max, add_media_rows(ctx, s, t));
  t.reading = fmt::format(
      "For dielectrics the symmetric F0 adjustment is exact at normal incidence and Schlick stays "
      "close; in a medium "
      "of their own index the exact reflectance vanishes (largest {:.1e}) while Schlick still "
      "brightens towards "
      "grazing. For metals neither adjustment knows η and κ separately; compare both columns "
      "before trusting one.",
      own_max);
  t.notes = media_notes(studies);
  return t;
}

Table internal_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  Table t;
  t.name = "internal";
  t.title =
      "Internal reflection: dielectrics seen from inside, exact against Schlick with the "
      "transmission angle";
  t.columns = {{"material"},
               {"critical_angle_deg", 2},
               {"rms_de00", 3},
               {"mean_de00", 3},
               {"max_de00", 3},
               {"de00_normal", 3},
               {"exact_at_critical", 6},
               {"schlick_at_critical", 6}};
  add_coverage_columns(t);
  std::vector<const LoadedMaterial*> dielectrics;
  for (const auto& s : studies) {
    if (s.is_metal()) continue;
    t.rows.push_back(internal_row(ctx, s));
    dielectrics.push_back(s.material);
  }
  t.reading =
      "Seen from inside, both curves start at F0 and end in total internal reflection; Schlick "
      "with the "
      "transmission angle follows the exact curve closely below the critical angle.";
  t.notes = {
      "exact: spectral Fresnel with relative index 1/n(λ) (κ neglected inside), including total "
      "internal "
      "reflection; Schlick: per channel with n = (1 + √F0)/(1 − √F0) and cos θt from Snell's law, "
      "1 past the "
      "critical angle.",
      "critical_angle_deg: the smallest angle past which every wavelength and every channel is "
      "totally "
      "reflected; the last two columns are the smallest RGB channel just past it (1 means total "
      "reflection).",
      coverage_note(dielectrics)};
  return t;
}

}  // namespace fl::analysis
