#include "report/figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "color/ocio.h"

namespace fl::report {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
const Rgb8 kInk{30, 30, 30};
const Rgb8 kGreyInk{110, 110, 110};

std::string settings_line(const analysis::Context& ctx) {
  const auto& s = ctx.settings();
  return fmt::format("{} working space, {} illuminant; sRGB display encoding by OpenColorIO", s.space, s.illuminant);
}

color::Rgb model_rgb(const ModelCurve& m, double cos_theta) {
  return fresnel::model_spec(m.model).evaluate(cos_theta, m.params.data(), false);
}

std::vector<color::Rgb> model_curve(const analysis::Context& ctx, const ModelCurve& m) {
  return fresnel::evaluate_curve(m.model, m.params, ctx.cos_thetas());
}

}  // namespace

std::vector<std::uint8_t> display_encode(const analysis::Context& ctx, const std::vector<float>& working_rgb) {
  const auto m = ctx.spaces().conversion(ctx.settings().space, "lin_rec709");
  std::vector<float> rgb(working_rgb.size());
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const auto o = color::transform_rgb(m, {working_rgb[i], working_rgb[i + 1], working_rgb[i + 2]});
    rgb[i] = static_cast<float>(o.r);
    rgb[i + 1] = static_cast<float>(o.g);
    rgb[i + 2] = static_cast<float>(o.b);
  }
  color::SpaceLibrary::encode_srgb_display(rgb);
  std::vector<std::uint8_t> out(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) out[i] = static_cast<std::uint8_t>(std::lround(255.0f * rgb[i]));
  return out;
}

Image8 strip_figure(const analysis::Context& ctx, const FigureInput& in, Font& font) {
  // Layout (pixels): labels | 0°–90° strip (6 px per degree) | gap | 80°–90° zoom (30 px per degree) | RMS ΔE.
  constexpr int kMargin = 16, kLabelW = 190, kMainW = 540, kGap = 36, kZoomW = 300, kErrW = 100;
  constexpr int kTop = 84, kRowH = 30, kRowGap = 6;
  const int main_x = kMargin + kLabelW, zoom_x = main_x + kMainW + kGap, err_x = zoom_x + kZoomW + 14;
  const int rows = 1 + static_cast<int>(in.models.size());
  const int strips_bottom = kTop + rows * (kRowH + kRowGap) - kRowGap;
  Image8 img(err_x + kErrW + kMargin, strips_bottom + 56);

  font.draw(img, kMargin, 26, fmt::format("{}: Fresnel reflectance, ground truth and models ({} parameters)",
                                          in.material, in.parameter_kind), 17, kInk);
  font.draw(img, kMargin, 46, settings_line(ctx), 12, kGreyInk);
  font.draw(img, main_x + kMainW / 2, kTop - 10, "incidence angle 0°–90°", 13, kInk, Align::Center);
  font.draw(img, zoom_x + kZoomW / 2, kTop - 10, "zoom 80°–90°", 13, kInk, Align::Center);
  font.draw(img, err_x, kTop - 10, "RMS ΔE2000", 13, kInk);

  // Every strip column's colour, all rows at once, encoded in one OCIO pass.
  struct Span {
    int x, width;
    double theta0, theta1;
  };
  const Span spans[] = {{main_x, kMainW, 0.0, 90.0}, {zoom_x, kZoomW, 80.0, 90.0}};
  const int columns = kMainW + kZoomW;
  std::vector<float> working(static_cast<size_t>(rows) * columns * 3);
  const double eta_e = ctx.settings().eta_outside;
  int col = 0;
  for (const auto& sp : spans)
    for (int x = 0; x < sp.width; ++x, ++col) {
      const double theta = sp.theta0 + (sp.theta1 - sp.theta0) * (x + 0.5) / sp.width;
      const double c = std::cos(theta * kDegToRad);
      for (int r = 0; r < rows; ++r) {
        const color::Rgb v = r == 0 ? analysis::ground_truth_rgb(ctx, *in.ior, c, eta_e) : model_rgb(in.models[r - 1], c);
        float* p = &working[3 * (static_cast<size_t>(r) * columns + col)];
        p[0] = static_cast<float>(v.r), p[1] = static_cast<float>(v.g), p[2] = static_cast<float>(v.b);
      }
    }
  const auto display = display_encode(ctx, working);

  const auto truth = analysis::ground_truth_curve(ctx, *in.ior, eta_e);
  for (int r = 0; r < rows; ++r) {
    const int y0 = kTop + r * (kRowH + kRowGap);
    const int baseline = y0 + kRowH / 2 + 5;
    col = 0;
    for (const auto& sp : spans)
      for (int x = 0; x < sp.width; ++x, ++col) {
        const std::uint8_t* p = &display[3 * (static_cast<size_t>(r) * columns + col)];
        img.fill_rect(sp.x + x, y0, 1, kRowH, {p[0], p[1], p[2]});
      }
    if (r == 0) {
      font.draw(img, main_x - 10, baseline, "ground truth (spectral)", 13, kInk, Align::Right);
      font.draw(img, err_x, baseline, "—", 13, kGreyInk);
    } else {
      const auto& m = in.models[r - 1];
      font.draw(img, main_x - 10, baseline, fresnel::model_spec(m.model).name, 13, kInk, Align::Right);
      const auto err = analysis::curve_error(ctx, truth, model_curve(ctx, m));
      font.draw(img, err_x, baseline, fmt::format("{:.2f}", err.rms), 13, kInk);
    }
  }
  // Angle ticks under the strips.
  const auto ticks = [&](const Span& sp, double step, double label_step) {
    for (double t = sp.theta0; t <= sp.theta1 + 1e-9; t += step) {
      const int x = sp.x + static_cast<int>(std::lround((t - sp.theta0) / (sp.theta1 - sp.theta0) * sp.width));
      const bool labelled = std::fabs(std::remainder(t, label_step)) < 1e-9;
      img.fill_rect(std::min(x, sp.x + sp.width - 1), strips_bottom + 2, 1, labelled ? 7 : 4, kInk);
      if (labelled) font.draw(img, x, strips_bottom + 24, fmt::format("{:g}°", t), 12, kInk, Align::Center);
    }
  };
  ticks(spans[0], 5.0, 10.0);
  ticks(spans[1], 1.0, 2.0);
  // Where the zoom sits on the full strip.
  const int z0 = main_x + kMainW * 80 / 90;
  img.fill_rect(z0, strips_bottom + 32, main_x + kMainW - z0, 2, kGreyInk);
  font.draw(img, z0 - 6, strips_bottom + 40, "zoomed", 11, kGreyInk, Align::Right);
  return img;
}

Drawing curves_drawing(const analysis::Context& ctx, const FigureInput& in) {
  static const Rgb8 kChannel[3] = {{205, 40, 40}, {30, 150, 50}, {40, 80, 210}};
  static const Rgb8 kModel[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}};
  static const Dash kDash[] = {{9, 5}, {2, 4}, {12, 4, 3, 4}, {5, 5}, {16, 5}, {3, 3, 3, 8}, {1, 3}, {7, 3, 1, 3}};
  constexpr int kN = 8;

  Drawing d;
  d.width = 940;
  d.height = 820;
  d.texts.push_back({24, 28, fmt::format("{}: reflectance and ΔE2000 against angle ({} parameters)", in.material,
                                         in.parameter_kind), 17, kInk, Align::Left, false});
  d.texts.push_back({24, 48, fmt::format("{} working space, {} illuminant; ΔE2000 against the spectral ground truth",
                                         ctx.settings().space, ctx.settings().illuminant), 12, kGreyInk, Align::Left,
                     false});

  const auto& deg = ctx.angles_deg();
  const double eta_e = ctx.settings().eta_outside;
  const auto truth = analysis::ground_truth_curve(ctx, *in.ior, eta_e);
  std::vector<std::vector<color::Rgb>> curves;
  for (const auto& m : in.models) curves.push_back(model_curve(ctx, m));

  // Panel 1: reflectance.
  const Axes top{90, 80, 620, 390, 0, 90, 0, 1};
  const std::vector<double> angle_ticks{0, 10, 20, 30, 40, 50, 60, 70, 80, 90};
  add_axes(d, top, angle_ticks, nice_ticks(0, 1, 5), "", "reflectance", 0, 1);
  const auto channel = [](const std::vector<color::Rgb>& c, int k) {
    std::vector<double> v;
    for (const auto& rgb : c) v.push_back(rgb[k]);
    return v;
  };
  for (size_t m = 0; m < curves.size(); ++m)
    for (int k = 0; k < 3; ++k) d.lines.push_back(data_line(top, deg, channel(curves[m], k), kChannel[k], 1.5, kDash[m % kN]));
  for (int k = 0; k < 3; ++k) d.lines.push_back(data_line(top, deg, channel(truth, k), kChannel[k], 2.2));

  // Panel 2: ΔE2000.
  std::vector<std::vector<double>> des;
  double de_max = 0;
  for (const auto& c : curves) {
    des.push_back(analysis::de2000_per_angle(ctx, truth, c));
    for (double v : des.back())
      if (std::isfinite(v)) de_max = std::max(de_max, v);
  }
  const Axes bottom{90, 530, 620, 220, 0, 90, 0, nice_ceiling(std::max(de_max, 0.5))};
  const auto de_ticks = nice_ticks(0, bottom.y_max, 4);
  const int de_decimals = bottom.y_max < 2 ? 1 : 0;
  add_axes(d, bottom, angle_ticks, de_ticks, "incidence angle θ (degrees)", "ΔE2000", 0, de_decimals);
  for (size_t m = 0; m < des.size(); ++m) d.lines.push_back(data_line(bottom, deg, des[m], kModel[m % kN], 1.8, kDash[m % kN]));

  // Legend.
  double y = 96;
  const double lx = 730;
  d.texts.push_back({lx, y, "reflectance (top)", 13, kInk, Align::Left, false});
  y += 20;
  for (int k = 0; k < 3; ++k) {
    d.lines.push_back({{{lx, y - 4}, {lx + 34, y - 4}}, kChannel[k], 2.2, {}});
    d.texts.push_back({lx + 42, y, std::string(1, "RGB"[k]) + " ground truth", 12, kInk, Align::Left, false});
    y += 18;
  }
  d.texts.push_back({lx, y, "models: same colours, dashed", 12, kGreyInk, Align::Left, false});
  y += 34;
  d.texts.push_back({lx, y, "models (dash styles)", 13, kInk, Align::Left, false});
  y += 20;
  for (size_t m = 0; m < in.models.size(); ++m) {
    d.lines.push_back({{{lx, y - 4}, {lx + 34, y - 4}}, kModel[m % kN], 1.8, kDash[m % kN]});
    const auto err = analysis::curve_error(ctx, truth, curves[m]);
    d.texts.push_back({lx + 42, y, fmt::format("{} ({:.2f})", fresnel::model_spec(in.models[m].model).name, err.rms),
                       12, kInk, Align::Left, false});
    y += 18;
  }
  d.texts.push_back({lx, y + 4, "(RMS ΔE2000)", 12, kGreyInk, Align::Left, false});
  return d;
}

Image8 sphere_display(const analysis::Context& ctx, const analysis::SphereImage& img) {
  constexpr float kBackground = 0.02f;  // linear grey behind the sphere
  std::vector<float> working(img.rgb.size());
  for (size_t k = 0; k < img.alpha.size(); ++k)
    for (int c = 0; c < 3; ++c) working[3 * k + c] = img.rgb[3 * k + c] + (1.0f - img.alpha[k]) * kBackground;
  Image8 out;
  out.width = img.width;
  out.height = img.height;
  out.pixels = display_encode(ctx, working);
  return out;
}

namespace {

// Five control points of matplotlib's "inferno" (van der Walt & Smith 2015, CC0), sRGB-encoded,
// interpolated linearly between them.
Rgb8 inferno(double t) {
  static const double kStops[5][3] = {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const double f = t - i;
  const auto ch = [&](int c) {
    return static_cast<std::uint8_t>(std::lround(kStops[i][c] + (kStops[i + 1][c] - kStops[i][c]) * f));
  };
  return {ch(0), ch(1), ch(2)};
}

}  // namespace

Image8 heatmap_figure(const std::vector<double>& de, int width, int height, const std::string& title, Font& font) {
  double de_max = 0;
  for (double v : de)
    if (std::isfinite(v)) de_max = std::max(de_max, v);
  const double scale = nice_ceiling(std::max(1.0, de_max));
  constexpr int kTop = 34, kBarW = 18, kRight = 110;
  Image8 img(width + kRight, height + kTop + 8, {255, 255, 255});
  font.draw(img, 8, 22, title, 13, kInk);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double v = de[static_cast<size_t>(y) * width + x];
      img.set(x, kTop + y, std::isfinite(v) ? inferno(v / scale) : Rgb8{235, 235, 235});
    }
  // Colour bar with ticks.
  const int bx = width + 16, by = kTop + 10, bh = height - 20;
  for (int y = 0; y < bh; ++y) img.fill_rect(bx, by + y, kBarW, 1, inferno(1.0 - (y + 0.5) / bh));
  for (double t : nice_ticks(0, scale, 4)) {
    const int y = by + static_cast<int>(std::lround((1.0 - t / scale) * (bh - 1)));
    img.fill_rect(bx + kBarW, y, 4, 1, kInk);
    font.draw(img, bx + kBarW + 7, y + 4, fmt::format("{:g}", t), 11, kInk);
  }
  font.draw(img, bx, by - 2 + bh + 16, "ΔE2000", 11, kInk);
  font.draw(img, bx, kTop + 2, fmt::format("max {:.2f}", de_max), 10, kGreyInk);
  return img;
}

}  // namespace fl::report
