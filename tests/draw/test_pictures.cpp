// Sphere renders (mirror centre pixel, MIS against quadrature), the Cairo drawing path (PNG, SVG,
// PDF), the figures and the plot / render / speed commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "analysis/render/figure_data.h"
#include "analysis/render/render.h"
#include "draw/drawing.h"
#include "draw/figures.h"
#include "draw/png.h"
#include "draw/speed_plot.h"
#include "fresnel/registry.h"
#include "io/exr.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl {
namespace {

using analysis::Environment;
using brdf::Vec3;

// The acceptance bound: a mirror sphere's centre pixel is F0 × the key light's radiance.
constexpr double kMirrorCentreTol = 1e-3;
// 4096 Hammersley samples per strategy against a fine midpoint quadrature of the same integral
// (measured: 5e-4 off at 4096 samples, 4e-3 at 256; the quasi-Monte Carlo error falls about as
// 1/N).
constexpr int kShadingSamples = 4096;
constexpr double kShadingQuadratureTol = 2e-3;
// One 8-bit display code.
constexpr int kOneCode = 1;

analysis::Settings test_settings() {
  analysis::Settings s;
  s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
  return s;
}

const analysis::Context& test_context() {
  static const analysis::Context ctx(test_settings());
  return ctx;
}

color::Rgb centre_pixel(const analysis::SphereImage& img) {
  const size_t k = static_cast<size_t>(img.height / 2) * img.width + img.width / 2;
  return {img.rgb[3 * k], img.rgb[3 * k + 1], img.rgb[3 * k + 2]};
}

TEST(Render, MirrorCentrePixelIsF0TimesTheKeyLight) {
  const auto& ctx = test_context();
  for (const char* name : {"gold", "chromium", "copper", "diamond"}) {
    const auto m =
        analysis::load_material(ctx, spectral::resolve_material(name, ctx.settings().paths));
    const color::Rgb f0 = analysis::ground_truth_rgb(ctx, m.ior, 1.0, 1.0);
    auto env = analysis::default_environment();
    env.key_radiance = {2.5, 1.5, 0.75};  // not white, so a channel mix-up would show
    analysis::RenderSettings rs;
    rs.size_px = 33;
    rs.roughness = 0.0;
    rs.threads = 1;
    const auto img =
        analysis::render_sphere(env, analysis::truth_fresnel_table(ctx, m.ior, 1.0), rs);
    const auto c = centre_pixel(img);
    EXPECT_NEAR(c.r, f0.r * env.key_radiance.r, kMirrorCentreTol) << name;
    EXPECT_NEAR(c.g, f0.g * env.key_radiance.g, kMirrorCentreTol) << name;
    EXPECT_NEAR(c.b, f0.b * env.key_radiance.b, kMirrorCentreTol) << name;
    EXPECT_FLOAT_EQ(img.alpha[static_cast<size_t>(16) * 33 + 16], 1.0f);
    // Gold's F0 is far from grey: the check is not passing on a neutral value by accident.
    if (std::string(name) == "gold") {
      EXPECT_GT(f0.r - f0.b, 0.3);
    }
  }
}

TEST(Render, MirrorCentrePixelWithAModelIsItsF0) {
  const std::vector<double> schlick_f0{0.95, 0.64, 0.54};
  const auto env = analysis::default_environment();
  analysis::RenderSettings rs;
  rs.size_px = 17;
  rs.roughness = 0.0;
  rs.threads = 2;
  const auto c = centre_pixel(analysis::render_sphere(
      env, analysis::model_fresnel_table(fresnel::model_of<fresnel::models::Schlick>, schlick_f0),
      rs));
  EXPECT_NEAR(c.r, 0.95 * env.key_radiance.r, kMirrorCentreTol);
  EXPECT_NEAR(c.g, 0.64 * env.key_radiance.g, kMirrorCentreTol);
  EXPECT_NEAR(c.b, 0.54 * env.key_radiance.b, kMirrorCentreTol);
}

// ∫ D V F (n·l) L(l) dω by a midpoint rule over the hemisphere (θ, φ), F ≡ 1: the reference the
// importance-sampled shading must match.
double quadrature(const Environment& env, const Vec3& v, double alpha) {
  constexpr int kTheta = 2000, kPhi = 480;
  double sum = 0;
  for (int i = 0; i < kTheta; ++i) {
    const double th = (i + 0.5) * (0.5 * std::numbers::pi / kTheta);
    for (int j = 0; j < kPhi; ++j) {
      const double ph = (j + 0.5) * (2.0 * std::numbers::pi / kPhi);
      const Vec3 l{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      // World frame = local frame here: n = +z.
      sum += brdf::ggx_lobe_cos(v, l, alpha) * environment_radiance(env, l).r * std::sin(th);
    }
  }
  return sum * (0.5 * std::numbers::pi / kTheta) * (2.0 * std::numbers::pi / kPhi);
}

TEST(Render, ImportanceSampledShadingMatchesQuadrature) {
  const analysis::FresnelTable one = analysis::tabulate_fresnel(
      [](double) {
        return color::Rgb{1, 1, 1};
      },
      2);
  const Vec3 n{0, 0, 1};
  const double alpha = 0.3 * 0.3;
  // (a) a white furnace: the result is the lobe's directional albedo, below 1.
  Environment white = analysis::default_environment();
  white.zenith = white.horizon = white.ground = white.key_radiance = {1, 1, 1};
  // (b) only the key light (a cone the view-side lobe partly covers): exercises the MIS weights.
  Environment key_only = analysis::default_environment();
  key_only.zenith = key_only.horizon = key_only.ground = {0, 0, 0};
  for (const Vec3 v : {Vec3{0, 0, 1}, brdf::normalize(Vec3{0.3, -0.2, 1.0})}) {
    const double furnace = analysis::shade_specular(white, one, n, v, alpha, kShadingSamples).r;
    EXPECT_NEAR(furnace, quadrature(white, v, alpha), kShadingQuadratureTol);
    EXPECT_LT(furnace, 1.0);
    const double key = analysis::shade_specular(key_only, one, n, v, alpha, kShadingSamples).r;
    EXPECT_NEAR(key, quadrature(key_only, v, alpha), kShadingQuadratureTol);
    EXPECT_GT(key, 0.1);  // the key light is in view of the lobe
  }
}

TEST(Render, DeterministicAcrossThreadCounts) {
  const auto env = analysis::default_environment();
  const auto table =
      analysis::model_fresnel_table(fresnel::model_of<fresnel::models::Schlick>, {0.9, 0.6, 0.3});
  analysis::RenderSettings rs;
  rs.size_px = 41;
  rs.samples = 8;
  rs.threads = 1;
  const auto a = analysis::render_sphere(env, table, rs);
  rs.threads = 3;
  const auto b = analysis::render_sphere(env, table, rs);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(a.alpha, b.alpha);
  EXPECT_FLOAT_EQ(a.alpha[0], 0.0f);  // a corner is background
}

// IEC 61966-2-1 (sRGB): the encoding of a linear value in [0, 1], as an 8-bit code.
int srgb_code(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  const double v =
      linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(255.0 * v));
}

// ACEScg (AP1) → linear Rec.709 with Bradford adaptation, as published with the ACES OCIO configs.
color::Rgb acescg_to_rec709(const color::Rgb& v) {
  static const double m[3][3] = {
      {1.70505, -0.62179, -0.08326}, {-0.13026, 1.14080, -0.01055}, {-0.02400, -0.12897, 1.15297}};
  return {m[0][0] * v.r + m[0][1] * v.g + m[0][2] * v.b,
          m[1][0] * v.r + m[1][1] * v.g + m[1][2] * v.b,
          m[2][0] * v.r + m[2][1] * v.g + m[2][2] * v.b};
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + what.size())) ++n;
  return n;
}

// Pixel bounds of everything darker than mid-grey.
struct Ink {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
Ink ink(const io::Image8& img) {
  Ink b;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.at(x, y).r < 128)
        b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x),
        b.y1 = std::max(b.y1, y);
  return b;
}

io::Image8 draw_png(const draw::Drawing& d, const draw::LabelFont& font) {
  test::TempDir tmp;
  const auto path = tmp.file("d.png", draw::encode(d, draw::FileType::Png, font));
  return draw::read_png(path);
}

TEST(Png, RoundTripSizeAndDeterministicBytes) {
  io::Image8 img(7, 5, io::Rgb8{10, 20, 30});
  img.set(3, 2, {255, 0, 128});
  const auto bytes = draw::encode_png(img);
  EXPECT_EQ(bytes, draw::encode_png(img));
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(bytes.find("tIME"), std::string::npos);  // no timestamp
  EXPECT_EQ(bytes.find("tEXt"), std::string::npos);
  test::TempDir tmp;
  const auto path = tmp.path() + "/x.png";
  draw::write_png_atomic(path, img);
  const auto back = draw::read_png(path);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.pixels, img.pixels);
  EXPECT_THROW(draw::read_png(tmp.file("bad.png", "not a png")), InputError);
}

TEST(Draw, HairlinesAndRectanglesCoverWholePixels) {
  draw::Drawing d;
  d.width = 40;
  d.height = 20;
  // A 1 px line along the centres of row 4 covers that row and nothing beyond it.
  d.add(draw::Polyline{{{2, 4.5}, {30, 4.5}}, {0, 0, 0}, 1.0, {}});
  d.add(draw::Rect{10, 10, 5, 3, {200, 40, 90}});
  const auto img = draw_png(d, draw::LabelFont());
  ASSERT_EQ(img.width, 40);
  ASSERT_EQ(img.height, 20);
  EXPECT_EQ(img.at(15, 4), (io::Rgb8{0, 0, 0}));
  EXPECT_EQ(img.at(15, 3), (io::Rgb8{255, 255, 255}));
  EXPECT_EQ(img.at(15, 5), (io::Rgb8{255, 255, 255}));
  EXPECT_EQ(img.at(10, 10), (io::Rgb8{200, 40, 90}));
  EXPECT_EQ(img.at(14, 12), (io::Rgb8{200, 40, 90}));
  EXPECT_EQ(img.at(15, 12), (io::Rgb8{255, 255, 255}));  // the rectangle ends at x = 15
  EXPECT_EQ(img.at(14, 13), (io::Rgb8{255, 255, 255}));
}

TEST(Draw, TextIsAlignedOnItsAnchor) {
  const draw::LabelFont font;
  const auto drawn = [&font](draw::Align align, bool vertical) {
    draw::Drawing d;
    d.width = 240;
    d.height = 240;
    d.add(draw::Text{120, 120, "Fresnel", 20, {0, 0, 0}, align, vertical});
    return ink(draw_png(d, font));
  };
  constexpr int kInkTol = 3;  // glyph side bearings, pixels
  const Ink centre = drawn(draw::Align::Center, false);
  ASSERT_GE(centre.x1, 0) << "no text drawn";
  EXPECT_NEAR(0.5 * (centre.x0 + centre.x1), 120, kInkTol);
  EXPECT_LE(centre.y1, 120);       // "Fresnel" has no descender: ink ends on the baseline
  EXPECT_GE(centre.y0, 120 - 20);  // and its capitals stay within the em size
  const Ink left = drawn(draw::Align::Left, false), right = drawn(draw::Align::Right, false);
  EXPECT_NEAR(left.x0, 120, kInkTol);
  EXPECT_NEAR(right.x1, 120, kInkTol);
  const Ink up = drawn(draw::Align::Left, true);
  EXPECT_GT(up.y1 - up.y0, 2 * (up.x1 - up.x0));  // reads upwards: taller than wide
  EXPECT_NEAR(0.5 * (up.y0 + up.y1), 120, kInkTol);
  EXPECT_NEAR(draw::text_width_px("Fresnel", 20, font), centre.x1 - centre.x0, 2 * kInkTol);
}

// Advance widths of "Fresnel" in font units (2048 per em), from the hmtx tables of Debian's
// fonts-dejavu-core 2.37 files: DejaVu Sans F r e s n e l = 1178 842 1260 1067 1298 1260 569;
// DejaVu Sans Mono sets every glyph 1233 wide.
constexpr double kSansFresnelUnits = 1178 + 842 + 1260 + 1067 + 1298 + 1260 + 569;
constexpr double kMonoFresnelUnits = 7 * 1233;
// Hinted metrics round each glyph's advance to whole pixels: at most half a pixel per glyph.
constexpr double kHintedTol = 7 * 0.5;

TEST(LabelFont, EachObjectSetsTextInItsOwnFile) {
  const draw::LabelFont sans;
  EXPECT_EQ(std::filesystem::path(sans.file()).filename(), "DejaVuSans.ttf");
  const auto mono_file = std::filesystem::path(sans.file()).parent_path() / "DejaVuSansMono.ttf";
  ASSERT_TRUE(std::filesystem::exists(mono_file)) << "fonts-dejavu-core installs " << mono_file;
  const draw::LabelFont mono(mono_file.string());
  EXPECT_EQ(mono.file(), mono_file.string());
  // Both loaded in one process, each measures with its own face.
  EXPECT_NEAR(draw::text_width_px("Fresnel", 20, sans), kSansFresnelUnits / 2048 * 20, kHintedTol);
  EXPECT_NEAR(draw::text_width_px("Fresnel", 20, mono), kMonoFresnelUnits / 2048 * 20, kHintedTol);
  // A copy shares the face and measures the same.
  const draw::LabelFont copy = mono;
  EXPECT_NEAR(draw::text_width_px("Fresnel", 20, copy), kMonoFresnelUnits / 2048 * 20, kHintedTol);
  // Drawn text follows the font passed to encode: the monospaced word is wider by the difference.
  draw::Drawing d;
  d.width = 240;
  d.height = 60;
  d.add(draw::Text{20, 40, "Fresnel", 20, {0, 0, 0}});
  const Ink a = ink(draw_png(d, sans)), b = ink(draw_png(d, mono));
  EXPECT_NEAR((b.x1 - b.x0) - (a.x1 - a.x0), (kMonoFresnelUnits - kSansFresnelUnits) / 2048 * 20,
              2 * kHintedTol);
}

TEST(LabelFont, AFileThatIsNoFontIsAnInputErrorNamingIt) {
  test::TempDir tmp;
  for (const auto& file : {tmp.path() + "/none.ttf", tmp.file("text.ttf", "not a font")}) {
    try {
      draw::LabelFont font(file);
      ADD_FAILURE() << file << " loaded";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file);
      EXPECT_EQ(std::string(e.what()),
                file + ": cannot load the label font (a TrueType or OpenType file)");
    }
  }
}

TEST(Draw, SvgIsWellFormedXmlAndPdfHasOnePage) {
  draw::Drawing d;
  d.width = 320;
  d.height = 200;
  d.add(draw::Text{10, 30, "ΔE2000 & <θ>", 14, {0, 0, 0}});
  d.add(draw::Polyline{{{10, 50}, {300, 150}}, {40, 80, 210}, 2.0, {6, 3}});
  d.add(draw::Circle{100, 100, 6, {255, 127, 14}, 2.0});
  d.add(draw::Picture{200, 20, io::Image8(30, 10, io::Rgb8{10, 200, 30})});
  test::TempDir tmp;
  const draw::LabelFont font;
  const auto svg = draw::encode(d, draw::FileType::Svg, font);
  const auto svg_path = tmp.file("d.svg", svg);
  if (std::system("command -v xmllint >/dev/null 2>&1") == 0) {
    const auto r = test::run_command("xmllint --noout '" + svg_path + "'");
    EXPECT_EQ(r.status, 0) << r.err;
  }
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("width=\"320px\" height=\"200px\""), std::string::npos);
  EXPECT_EQ(count(svg, "<svg"), 1u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(svg, draw::encode(d, draw::FileType::Svg, font));  // Cairo's surface counters moved on
  const auto pdf = draw::encode(d, draw::FileType::Pdf, font);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_EQ(count(pdf, "/Type /Page\n") + count(pdf, "/Type /Page "), 1u);
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 320 200 ]"), std::string::npos);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
  EXPECT_EQ(pdf.find("/CreationDate"), std::string::npos);  // nothing that changes between runs
  EXPECT_EQ(pdf, draw::encode(d, draw::FileType::Pdf, font));
  EXPECT_EQ(draw::file_type("A.PDF"), draw::FileType::Pdf);
  EXPECT_THROW(draw::file_type("a.jpg"), InputError);
}

TEST(Figures, WhiteDisplaysAsWhite) {
  // The working space's white (ACES white in ACEScg) is D65 white in linear Rec.709 after OCIO's
  // Bradford adaptation, and encodes to 255.
  const auto white = analysis::display_encode(test_context(), {1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f});
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(white[c], 255, kOneCode);
    EXPECT_EQ(white[3 + c], 0);
  }
}

// A dielectric of constant index n = 1.5 reflects ((n − 1)/(n + 1))² = 0.04 at every wavelength at
// normal incidence, so its ground truth is the grey 0.04 × white; a Schlick model shows its F0.
TEST(Figures, StripPixelsAreTheSrgbEncodingOfKnownReflectances) {
  const auto& ctx = test_context();
  spectral::ComplexIorSpectrum glass{
      ctx.grid(), std::vector<std::complex<double>>(ctx.grid().count, {1.5, 0.0})};
  const color::Rgb f0{0.6, 0.45, 0.3};
  const analysis::FigureRequest in{
      "Test glass",
      "derived",
      &glass,
      {{fresnel::model_of<fresnel::models::Schlick>, {f0.r, f0.g, f0.b}}}};
  const auto data = analysis::strip_data(ctx, in);
  ASSERT_EQ(data.rows.size(), 2u);
  const auto img = draw_png(draw::strip_drawing(data), draw::LabelFont());
  // Sample 0 of the 0°–90° span is at θ = 1/12°, where both reflectances are their normal-incidence
  // values to 1e-6.
  const auto pixel = [&](size_t row) {
    const auto p = draw::strip_cell(data, row, 0, 0);
    return img.at(static_cast<int>(p.x), static_cast<int>(p.y) + draw::kStripRowHeight / 2);
  };
  const int grey = srgb_code(0.04);
  const auto truth = pixel(0);
  EXPECT_NEAR(truth.r, grey, kOneCode);
  EXPECT_NEAR(truth.g, grey, kOneCode);
  EXPECT_NEAR(truth.b, grey, kOneCode);
  const color::Rgb lin = acescg_to_rec709(f0);
  const auto schlick = pixel(1);
  EXPECT_NEAR(schlick.r, srgb_code(lin.r), kOneCode);
  EXPECT_NEAR(schlick.g, srgb_code(lin.g), kOneCode);
  EXPECT_NEAR(schlick.b, srgb_code(lin.b), kOneCode);
  EXPECT_GT(schlick.r - schlick.b, 40);  // not grey: a channel mix-up would show
  // At grazing incidence every reflectance tends to 1: the zoom's last sample is near white.
  const auto p = draw::strip_cell(data, 1, 1, data.spans[1].samples - 1);
  EXPECT_GE(img.at(static_cast<int>(p.x), static_cast<int>(p.y) + 1).g, srgb_code(0.99));
  // The figure is exactly as wide as its strips plus the labels and the RMS column.
  EXPECT_EQ(img.width, static_cast<int>(draw::strip_cell(data, 0, 1, 0).x) + data.spans[1].samples +
                           14 + 100 + 16);
}

// CIEDE2000 between two neutral greys of lightness L1 and L2 (Sharma, Wu & Dalal 2005 with
// a* = b* = 0: every chroma and hue term vanishes, leaving ΔL' / S_L).
double neutral_de2000(double l1, double l2) {
  const double lbar = 0.5 * (l1 + l2), d = (lbar - 50) * (lbar - 50);
  return std::abs(l2 - l1) / (1 + 0.015 * d / std::sqrt(20 + d));
}

// CIE 1976 lightness of a luminance relative to white (Y > 0.008856).
double lightness(double y) {
  return 116 * std::cbrt(y) - 16;
}

// Under each model's strip, its ΔE2000 against the truth: a grey glass (n = 1.5, F0 = 0.04) against
// Schlick with F0 = 0.04 (ΔE ≈ 0 at normal incidence), with a grey 0.3 ΔE2000 lighter (found from
// the neutral-grey form of CIEDE2000) and with a colour (far beyond the scale's top).
TEST(Figures, StripsShowEachModelsDe2000UnderItsStrip) {
  const auto& ctx = test_context();
  spectral::ComplexIorSpectrum glass{
      ctx.grid(), std::vector<std::complex<double>>(ctx.grid().count, {1.5, 0.0})};
  double lo = 0.04, hi = 0.05;  // bisection for Y with ΔE2000(0.04, Y) = 0.3
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (neutral_de2000(lightness(0.04), lightness(mid)) < 0.3 ? lo : hi) = mid;
  }
  const auto schlick = [](double r, double g, double b) {
    return analysis::FigureModel{fresnel::model_of<fresnel::models::Schlick>, {r, g, b}};
  };
  const analysis::FigureRequest in{
      "Test glass",
      "derived",
      &glass,
      {schlick(0.04, 0.04, 0.04), schlick(lo, lo, lo), schlick(0.6, 0.45, 0.3)}};
  const auto data = analysis::strip_data(ctx, in);
  ASSERT_EQ(data.rows.size(), 4u);
  EXPECT_TRUE(data.rows[0].de2000.empty());
  constexpr double kDeTolerance = 1e-3;  // θ = 1/12° moves either reflectance by < 1e-6
  EXPECT_NEAR(data.rows[1].de2000[0], 0.0, kDeTolerance);
  EXPECT_NEAR(data.rows[2].de2000[0], 0.3, kDeTolerance);
  EXPECT_GT(data.rows[3].de2000[0], analysis::kStripDe2000Scale);
  const auto img = draw_png(draw::strip_drawing(data), draw::LabelFont());
  const auto de_pixel = [&](size_t row) {
    const auto p = draw::strip_cell(data, row, 0, 0);
    return img.at(static_cast<int>(p.x),
                  static_cast<int>(p.y) + draw::kStripRowHeight + draw::kStripDeOffset + 1);
  };
  const auto expect_colour = [](io::Rgb8 got, io::Rgb8 want) {
    EXPECT_NEAR(got.r, want.r, kOneCode);
    EXPECT_NEAR(got.g, want.g, kOneCode);
    EXPECT_NEAR(got.b, want.b, kOneCode);
  };
  expect_colour(de_pixel(1), draw::inferno(0.0));
  expect_colour(de_pixel(2), draw::inferno(0.3 / analysis::kStripDe2000Scale));
  expect_colour(de_pixel(3), draw::inferno(1.0));  // saturated
  // 0.3 ΔE2000 stands out from 0: its colour is tens of codes away from the zero colour.
  const auto a = de_pixel(1), b = de_pixel(2);
  EXPECT_GT(std::hypot(a.r - b.r, a.g - b.g, a.b - b.b), 40.0);
  // The strips themselves stay where strip_cell says: the model rows' colours are their F0 greys.
  const auto strip = [&](size_t row) {
    const auto p = draw::strip_cell(data, row, 0, 0);
    return img.at(static_cast<int>(p.x), static_cast<int>(p.y) + draw::kStripRowHeight / 2);
  };
  EXPECT_NEAR(strip(1).g, srgb_code(0.04), kOneCode);
  EXPECT_NEAR(strip(2).g, srgb_code(lo), kOneCode);
}

// matplotlib's inferno table (van der Walt & Smith 2015, CC0): first and last entries.
constexpr double kInfernoFirst[3] = {0.001462, 0.000466, 0.013866};
constexpr double kInfernoLast[3] = {0.988362, 0.998364, 0.644924};

io::Rgb8 codes(const double (&v)[3]) {
  const auto c = [](double x) { return static_cast<std::uint8_t>(std::lround(255.0 * x)); };
  return {c(v[0]), c(v[1]), c(v[2])};
}

TEST(Figures, HeatMapLegendEndsAreInfernosEnds) {
  constexpr int kW = 60, kH = 50;
  std::vector<double> de(kW * kH, 0.0);
  de[0] = std::nan("");
  de[kW * kH - 1] = 2.0;  // the largest ΔE is 2, a nice value: the scale's top
  const draw::LabelFont font;
  const auto img = draw_png(draw::heatmap_drawing(de, kW, kH, "test", font), font);
  const auto bar = draw::heatmap_colour_bar(kW, kH);
  ASSERT_GE(img.height, bar.y + bar.height);
  ASSERT_GE(img.width, bar.x + bar.width);
  const int mid = bar.x + bar.width / 2;
  EXPECT_EQ(img.at(mid, bar.y), codes(kInfernoLast));
  EXPECT_EQ(img.at(mid, bar.y + bar.height - 1), codes(kInfernoFirst));
  EXPECT_EQ(draw::inferno(1.0), codes(kInfernoLast));
  EXPECT_EQ(draw::inferno(0.0), codes(kInfernoFirst));
  // The map itself, below the title band: ΔE 0 and the top of the scale take the bar's end colours.
  const int top = draw::kHeatmapImageTop;
  EXPECT_EQ(img.at(kW - 1, top + kH - 1), codes(kInfernoLast));
  EXPECT_EQ(img.at(kW / 2, top + kH / 2), codes(kInfernoFirst));
  EXPECT_EQ(img.at(0, top), (io::Rgb8{235, 235, 235}));  // no surface
  // Tick marks at both ends of the bar, on its right edge.
  EXPECT_LT(img.at(bar.x + bar.width + 1, bar.y).r, 128);
  EXPECT_LT(img.at(bar.x + bar.width + 1, bar.y + bar.height - 1).r, 128);
}

// Published entries of matplotlib's 256-entry inferno table (_cm_listed.py, _inferno_data; entry i
// at t = i / 255).
constexpr double kInferno32[3] = {0.129285, 0.047293, 0.290788};
constexpr double kInferno33[3] = {0.135778, 0.046856, 0.299776};
constexpr double kInferno128[3] = {0.735683, 0.215906, 0.330245};
constexpr double kInferno224[3] = {0.974638, 0.797692, 0.206332};

// CIE 1976 L* of an 8-bit sRGB colour (IEC 61966-2-1 decoding, Rec.709 luminance, white Y = 1).
double lightness(io::Rgb8 c) {
  const auto lin = [](std::uint8_t code) {
    const double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  const double y = 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
  constexpr double kEps = 216.0 / 24389.0, kKappa = 24389.0 / 27.0;
  return y > kEps ? 116.0 * std::cbrt(y) - 16.0 : kKappa * y;
}

TEST(Figures, InfernoIsThePublishedTableInterpolatedLinearly) {
  EXPECT_EQ(draw::inferno(0.0), codes(kInfernoFirst));
  EXPECT_EQ(draw::inferno(32.0 / 255), codes(kInferno32));    // (33, 12, 74)
  EXPECT_EQ(draw::inferno(128.0 / 255), codes(kInferno128));  // (188, 55, 84)
  EXPECT_EQ(draw::inferno(224.0 / 255), codes(kInferno224));  // (249, 203, 53)
  EXPECT_EQ(draw::inferno(1.0), codes(kInfernoLast));
  // Halfway between two entries: their mean.
  const double mid[3] = {0.5 * (kInferno32[0] + kInferno33[0]),
                         0.5 * (kInferno32[1] + kInferno33[1]),
                         0.5 * (kInferno32[2] + kInferno33[2])};
  EXPECT_EQ(draw::inferno(32.5 / 255), codes(mid));  // (34, 12, 75)
  EXPECT_EQ(draw::inferno(-1.0), codes(kInfernoFirst));
  EXPECT_EQ(draw::inferno(2.0), codes(kInfernoLast));
  // The published map's lightness rises monotonically from black (L* 0.1) to pale yellow (L* 98);
  // the 8-bit codes at the 256 entries keep every step (the smallest is 0.04).
  double previous = -1;
  for (int i = 0; i < 256; ++i) {
    const double l = lightness(draw::inferno(i / 255.0));
    EXPECT_GT(l, previous) << "entry " << i;
    previous = l;
  }
  EXPECT_NEAR(lightness(draw::inferno(0.0)), 0.08, 0.01);
  EXPECT_NEAR(previous, 98.0, 0.1);
}

TEST(Figures, CurveAndSpeedFiguresHaveTheirSizes) {
  const auto& ctx = test_context();
  const auto m =
      analysis::load_material(ctx, spectral::resolve_material("chromium", ctx.settings().paths));
  const analysis::FigureRequest in{
      "Chromium",
      "derived",
      &m.ior,
      {{fresnel::model_of<fresnel::models::Schlick>, {0.55, 0.55, 0.56}}}};
  const auto curves = analysis::curve_data(ctx, in);
  ASSERT_EQ(curves.models.size(), 1u);
  EXPECT_EQ(curves.models[0].de2000.size(), ctx.angles_deg().size());
  // Schlick reaches 1 at 90°, like any Fresnel reflectance: no colour difference there.
  EXPECT_NEAR(curves.models[0].de2000.back(), 0.0, 1e-6);
  const draw::LabelFont font;
  const auto img = draw_png(draw::curves_drawing(curves), font);
  EXPECT_EQ(img.width, 940);
  EXPECT_EQ(img.height, 820);
  std::vector<analysis::SpeedRow> rows{
      {fresnel::model_of<fresnel::models::Schlick>, false, 0.5, 1.6, 3.0, false},
      {fresnel::model_of<fresnel::models::F82>, true, 1.5, 0.6, 2.0, true}};
  const auto speed = draw_png(draw::speed_plot(rows, font), font);
  EXPECT_EQ(speed.width, 960);
  EXPECT_EQ(speed.height, 560);
}

TEST(PictureCli, PlotAndRenderWriteTheirFiles) {
  using test::cli;
  using test::run_command;
  test::TempDir tmp;
  const auto strip = tmp.path() + "/s.png", curves = tmp.path() + "/c.svg",
             exr = tmp.path() + "/r.exr";
  ASSERT_EQ(
      run_command(cli() + " -q plot strip gold --models schlick,f82 --out '" + strip + "'").status,
      0);
  ASSERT_EQ(run_command(cli() + " -q plot curves gold --out '" + curves + "'").status, 0);
  ASSERT_EQ(run_command(cli() + " -q plot strip gold --out '" + tmp.path() + "/s.pdf'").status, 0);
  const auto r = run_command(
      cli() + " -q render gold --model f82 --roughness 0 --size 21 --samples 4 --out '" + exr +
      "'");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f :
       {"/s.png", "/c.svg", "/s.pdf", "/r.exr", "/r.png", "/r.truth.png", "/r.de2000.png"})
    EXPECT_TRUE(std::filesystem::exists(tmp.path() + f)) << f;
  EXPECT_EQ(draw::read_png(tmp.path() + "/r.png").width, 21);
  // $FRESNEL_LAB_FONT reaches the drawing: in DejaVu Sans Mono every glyph of the heat map's title
  // "Gold: ΔE2000, truth vs F82" (26 characters) advances 1233/2048 × 13 px, hinted to 8 px, and
  // the map is as wide as the title with 8 px margins (the map and its colour bar are narrower).
  const auto mono =
      std::filesystem::path(draw::LabelFont().file()).parent_path() / "DejaVuSansMono.ttf";
  ASSERT_EQ(run_command("FRESNEL_LAB_FONT='" + mono.string() + "' " + cli() +
                        " -q render gold --model f82 --roughness 0 --size 21 --samples 4 --out '" +
                        tmp.path() + "/m.exr'")
                .status,
            0);
  EXPECT_EQ(draw::read_png(tmp.path() + "/m.de2000.png").width, 8 + 26 * 8 + 8);
  EXPECT_NE(draw::read_png(tmp.path() + "/r.de2000.png").width, 8 + 26 * 8 + 8);
  EXPECT_EQ(slurp(tmp.path() + "/s.pdf").rfind("%PDF-", 0), 0u);
  const auto e = io::read_exr(exr);
  EXPECT_EQ(e.channels.size(), 4u);
  // Bad input: one line, exit 2, nothing written.
  const auto bad = run_command(cli() + " plot strip gold --out '" + tmp.path() + "/x.jpg'");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_EQ(run_command(cli() + " plot strip gold --models nosuch --out '" + tmp.path() + "/y.png'")
                .status,
            2);
  EXPECT_EQ(
      run_command(cli() + " render gold --roughness 2 --out '" + tmp.path() + "/z.exr'").status, 2);
  EXPECT_EQ(run_command(cli() + " speed --plot '" + tmp.path() + "/p.gif'").status, 2);
  const auto no_font = run_command("FRESNEL_LAB_FONT='" + tmp.path() + "/none.ttf' " + cli() +
                                   " plot strip gold --out '" + tmp.path() + "/f.png'");
  EXPECT_EQ(no_font.status, 2);
  EXPECT_EQ(std::count(no_font.err.begin(), no_font.err.end(), '\n'), 1) << no_font.err;
  for (const char* f : {"/x.jpg", "/z.exr", "/p.gif", "/f.png"})
    EXPECT_FALSE(std::filesystem::exists(tmp.path() + f)) << f;
  for (const char* cmd : {"plot", "plot strip", "plot curves", "render"})
    EXPECT_EQ(run_command(cli() + " " + cmd + " --help").status, 0) << cmd;
}

// Dielectric renders hold the reflection only: their pictures add it over mid grey 0.18 and say so;
// metals keep the dark backdrop 0.02. Through the Un-tone-mapped view a neutral working-space
// value v shows as the sRGB encoding of v (ACES white is D65 white after Bradford adaptation).
TEST(PictureCli, DielectricRendersShowTheirReflectionOverMidGrey) {
  using test::cli;
  using test::run_command;
  test::TempDir tmp;
  const auto render = [&](const std::string& material, const std::string& name) {
    return run_command(cli() + " --view Un-tone-mapped render '" + material +
                       "' --model schlick --roughness 0 --size 21 --samples 4 --out '" +
                       tmp.path() + "/" + name + ".exr'");
  };
  const auto glass = render("glass BK7", "g"), gold = render("gold", "m");
  ASSERT_EQ(glass.status, 0) << glass.err;
  ASSERT_EQ(gold.status, 0) << gold.err;
  EXPECT_NE(glass.err.find("reflection only (no transmission), added over mid grey 0.18"),
            std::string::npos)
      << glass.err;
  EXPECT_EQ(gold.err.find("reflection only"), std::string::npos);
  const auto g = draw::read_png(tmp.path() + "/g.png"), m = draw::read_png(tmp.path() + "/m.png");
  EXPECT_NEAR(g.at(0, 0).g, srgb_code(analysis::kMidGreyBackdrop), kOneCode);
  EXPECT_NEAR(m.at(0, 0).g, srgb_code(analysis::kDarkBackdrop), kOneCode);
  // The sphere's centre: its reflection (about 0.042, F0 of BK7 under a unit key light) over grey.
  const auto exr = io::read_exr(tmp.path() + "/g.exr");
  const size_t centre = 10 * 21 + 10, nc = exr.channels.size();
  const auto green = std::find(exr.channels.begin(), exr.channels.end(), "G");
  ASSERT_NE(green, exr.channels.end());
  const double reflection = exr.pixels[nc * centre + (green - exr.channels.begin())];
  EXPECT_NEAR(g.at(10, 10).g, srgb_code(reflection + analysis::kMidGreyBackdrop), kOneCode);
  // A view that does not exist: exit 2, one line, nothing written.
  const auto bad = run_command(cli() + " --reflectance-view nosuch plot strip gold --out '" +
                               tmp.path() + "/x.png'");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/x.png"));
}

TEST(PictureCli, FiguresAreByteIdenticalRunToRun) {
  using test::cli;
  using test::run_command;
  test::TempDir tmp;
  for (const char* ext : {".png", ".svg", ".pdf"})
    for (const char* run : {"a", "b"}) {
      const auto out = tmp.path() + "/" + run + ext;
      ASSERT_EQ(run_command(cli() + " -q plot curves copper --out '" + out + "'").status, 0) << out;
    }
  for (const char* ext : {".png", ".svg", ".pdf"}) {
    const auto a = slurp(tmp.path() + "/a" + ext), b = slurp(tmp.path() + "/b" + ext);
    EXPECT_FALSE(a.empty()) << ext;
    EXPECT_EQ(a, b) << ext;
  }
  EXPECT_EQ(draw::read_png(tmp.path() + "/a.png").width, 940);
}

}  // namespace
}  // namespace fl
