#include "analysis/render/figure_data.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "color/ocio.h"

namespace fl::analysis {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

FigureCaption caption(const Context& ctx, const FigureRequest& in) {
  return {in.material, in.parameter_kind, ctx.settings().space, ctx.settings().illuminant,
          ctx.reflectance_display().description()};
}

color::Rgb model_rgb(const FigureModel& m, double cos_theta) {
  return fresnel::model_spec(m.model).evaluate(cos_theta, m.params.data(), false);
}

// Working-space RGB of every row (truth, then models) at every sample: rows[r][column].
std::vector<std::vector<color::Rgb>> strip_samples(const Context& ctx, const FigureRequest& in,
                                                   const std::vector<StripSpan>& spans) {
  std::vector<std::vector<color::Rgb>> rows(1 + in.models.size());
  const double eta_e = ctx.settings().eta_outside;
  for (const auto& sp : spans)
    for (int i = 0; i < sp.samples; ++i) {
      const double theta = sp.theta0_deg + (sp.theta1_deg - sp.theta0_deg) * (i + 0.5) / sp.samples;
      const double c = std::cos(theta * kDegToRad);
      for (size_t r = 0; r < rows.size(); ++r)
        rows[r].push_back(r == 0 ? ground_truth_rgb(ctx, *in.ior, c, eta_e)
                                 : model_rgb(in.models[r - 1], c));
    }
  return rows;
}

std::vector<float> as_floats(const std::vector<color::Rgb>& v) {
  std::vector<float> out;
  for (const auto& c : v)
    out.insert(out.end(),
               {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)});
  return out;
}

}  // namespace

CurveData curve_data(const Context& ctx, const FigureRequest& in) {
  CurveData d;
  d.caption = caption(ctx, in);
  d.angles_deg = ctx.angles_deg();
  d.truth = ground_truth_curve(ctx, *in.ior, ctx.settings().eta_outside);
  for (const auto& m : in.models) {
    ModelCurveData c;
    c.name = fresnel::model_spec(m.model).name;
    c.rgb = fresnel::evaluate_curve(m.model, m.params, ctx.cos_thetas());
    c.de2000 = de2000_per_angle(ctx, d.truth, c.rgb);
    c.rms_de2000 = curve_error(ctx, d.truth, c.rgb).rms;
    d.models.push_back(std::move(c));
  }
  return d;
}

std::vector<StripSpan> default_strip_spans() {
  return {{0.0, 90.0, 540}, {80.0, 90.0, 300}};
}

StripData strip_data(const Context& ctx, const FigureRequest& in,
                     const std::vector<StripSpan>& spans) {
  StripData d;
  d.caption = caption(ctx, in);
  d.spans = spans;
  const auto samples = strip_samples(ctx, in, spans);
  const auto curves = curve_data(ctx, in);
  for (size_t r = 0; r < samples.size(); ++r) {
    StripRow row;
    row.label = r == 0 ? std::string("ground truth (spectral)") : curves.models[r - 1].name;
    if (r > 0) {
      row.rms_de2000 = curves.models[r - 1].rms_de2000;
      row.de2000 = de2000_per_angle(ctx, samples[0], samples[r]);
    }
    row.srgb = display_encode(ctx, as_floats(samples[r]));
    d.rows.push_back(std::move(row));
  }
  return d;
}

namespace {

std::vector<std::uint8_t> codes(const std::vector<float>& display) {
  std::vector<std::uint8_t> out(display.size());
  for (size_t i = 0; i < display.size(); ++i)
    out[i] = static_cast<std::uint8_t>(std::lround(255.0f * display[i]));
  return out;
}

}  // namespace

std::vector<std::uint8_t> display_encode(const Context& ctx,
                                         const std::vector<float>& working_rgb) {
  std::vector<float> rgb = working_rgb;
  ctx.reflectance_display().apply(rgb);
  return codes(rgb);
}

MaterialSwatches material_swatches(const Context& ctx, const spectral::ComplexIorSpectrum& ior,
                                   int samples) {
  std::vector<float> working;
  const double eta_e = ctx.settings().eta_outside;
  const auto push = [&](double cos_theta) {
    const color::Rgb v = ground_truth_rgb(ctx, ior, cos_theta, eta_e);
    working.insert(working.end(),
                   {static_cast<float>(v.r), static_cast<float>(v.g), static_cast<float>(v.b)});
  };
  for (int i = 0; i < samples; ++i)
    push(i + 1 == samples ? 0.0 : std::cos(90.0 * kDegToRad * i / (samples - 1)));
  push(1.0);
  push(1.0 / 7.0);
  const auto codes = display_encode(ctx, working);
  MaterialSwatches sw;
  sw.strip.assign(codes.begin(), codes.begin() + 3 * samples);
  std::copy(codes.end() - 6, codes.end() - 3, sw.f0.begin());
  std::copy(codes.end() - 3, codes.end(), sw.f82.begin());
  return sw;
}

Backdrop backdrop_for(spectral::MaterialClass c) {
  return c == spectral::MaterialClass::Dielectric ? Backdrop::ReflectionOnMidGrey : Backdrop::Dark;
}

bool reflection_only(spectral::MaterialClass c) {
  return backdrop_for(c) == Backdrop::ReflectionOnMidGrey;
}

std::vector<std::uint8_t> sphere_display(const color::DisplayTransform& view,
                                         const SphereImage& img, Backdrop backdrop) {
  return codes(sphere_display_values(view, img, backdrop));
}

std::vector<float> sphere_display_values(const color::DisplayTransform& view,
                                         const SphereImage& img, Backdrop backdrop) {
  std::vector<float> working(img.rgb.size());
  for (size_t k = 0; k < img.alpha.size(); ++k)
    for (int c = 0; c < 3; ++c)
      working[3 * k + c] =
          img.rgb[3 * k + c] +
          (backdrop == Backdrop::Dark ? (1.0f - img.alpha[k]) * kDarkBackdrop : kMidGreyBackdrop);
  view.apply(working);
  return working;
}

}  // namespace fl::analysis
