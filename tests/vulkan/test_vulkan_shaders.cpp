// Every shader the tool ships, executed on a conformant Vulkan implementation (Mesa's lavapipe on
// the test machines; the first device the loader lists), against the CPU engine model that the
// errors as rendered are computed with (analysis/lut/rendered.h). The tables are the files `lut`
// writes, uploaded as an engine uploads them (RGBA16F and RGBA32F, linear filtering, clamp to
// edge); their addressing is whatever the shipped lookups and the CPU model use (nothing here maps
// uv). No device is a failure, not a skip: scripts/setup.sh installs one.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "analysis/lut/lut_accuracy.h"
#include "analysis/pipeline/materials.h"
#include "color/lab.h"
#include "fresnel/registered_models.h"
#include "vulkan/shader_kernel.h"

namespace fl::test::vk {
namespace {

using analysis::Lighting;
using analysis::ShaderLanguage;

// Tolerances: shader_kernel.h. The CPU model's ΔE2000 is lut-accuracy's (rendered_de00), from
// tables of the same storage.

double tolerance(Storage s) {
  return s == Storage::Half ? kHalfTolerance : kFloatTolerance;
}

// Throws (the test fails) when there is no Vulkan device.
Device& device() {
  return shared_device();
}

TEST(VulkanShaders, DeviceFound) {
  ASSERT_NO_THROW(device()) << "no Vulkan device: scripts/setup.sh installs mesa-vulkan-drivers";
  std::printf("Vulkan device: %s (%s)\n", device().name().c_str(), device().driver().c_str());
  EXPECT_FALSE(device().name().empty());
}

// (n·v, roughness) over the tables' range: n·v from near 0 to 1, roughness 0 (the tables' first
// row, read as the _ibl and _area functions read it) to 1, and lut-accuracy's points.
std::vector<analysis::NovRoughness> grid() {
  std::vector<analysis::NovRoughness> at;
  for (double r : {0.0, 0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 0.98, 1.0})
    for (double nov : {1e-3, 0.02, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 1.0}) at.push_back({nov, r});
  for (double r : analysis::kDefaultRoughness)
    for (double deg : analysis::kShadingViewDeg)
      at.push_back({std::cos(deg * std::numbers::pi / 180.0), r});
  return at;
}

// The materials the models are run with (derived parameters): a metal of high and one of low
// colour saturation, and a glass.
struct Fixture {
  analysis::Context ctx{[] {
    analysis::Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  analysis::MaterialSet set = analysis::load_materials(ctx, {"gold", "silver", "glass_bk7"}, {});
  std::vector<analysis::MaterialStudy> studies = analysis::study_materials(ctx, set.materials, [] {
    analysis::StudyOptions o;
    o.fit = false;
    return o;
  }());
  // The tables' size as `lut` wrote them for the test (CTest fixture Vulkan.tables_dfg).
  int lut_size = read_texture(std::string(FL_VK_TABLES) + "/dfg.exr").width;
  // The CPU model's points reading the tables in each storage (the same angles and truth weights).
  std::map<Storage, std::vector<analysis::ShadingPoint>> storage_points{
      {Storage::Float, at_points(analysis::TexelStorage::Float)},
      {Storage::Half, at_points(analysis::TexelStorage::Half)}};
  const std::vector<analysis::ShadingPoint>& points = storage_points.at(Storage::Float);
  std::vector<std::vector<color::Rgb>> truth;  // per material, at points
  Fixture() {
    for (const auto& m : set.materials) truth.push_back(analysis::lobe_truth(ctx, m, points));
  }
  std::vector<analysis::ShadingPoint> at_points(analysis::TexelStorage s) const {
    return analysis::shading_points_at(grid(), false, 0, analysis::engine_tables(lut_size, s));
  }
  double de00(const color::Rgb& a, const color::Rgb& b) const {
    return color::ciede2000(ctx.rgb_to_lab(a), ctx.rgb_to_lab(b));
  }
};
const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// The largest differences of one run, and where.
struct Worst {
  double rgb = 0, de00 = 0;
  std::string rgb_at, de00_at;
  void add_rgb(double d, const std::string& at) {
    if (d > rgb) rgb = d, rgb_at = at;
  }
  void add_de00(double d, const std::string& at) {
    if (d > de00) de00 = d, de00_at = at;
  }
};

// The CPU model's RGB and ΔE2000 against the truth (lut-accuracy's rendered_de00) per point of one
// material; punctual: the model at cos θ = n·v against the spectral curve there.
struct Expected {
  std::vector<color::Rgb> rgb, truth;
  std::vector<double> de00;
};
Expected expected(fresnel::Model m, Lighting l, size_t material, const std::vector<double>& params,
                  Storage storage) {
  const auto& f = fixture();
  const auto& points = f.storage_points.at(storage);
  Expected e;
  for (size_t k = 0; k < f.points.size(); ++k) {
    const auto& p = f.points[k];
    if (l == Lighting::Punctual) {
      e.rgb.push_back(fresnel::model_spec(m).evaluate(p.nov, params.data(), false));
      e.truth.push_back(analysis::ground_truth_rgb(f.ctx, f.set.materials[material].ior, p.nov,
                                                   f.ctx.settings().eta_outside));
      e.de00.push_back(f.de00(e.truth.back(), e.rgb.back()));
    } else {
      e.rgb.push_back(analysis::engine_shading(m, params, l, points[k]));
      e.truth.push_back(f.truth[material][k]);
    }
  }
  if (l != Lighting::Punctual)
    e.de00 = analysis::rendered_de00(f.ctx, f.truth[material], m, params, l, points);
  return e;
}

std::string where(fresnel::Model m, Lighting l, ShaderLanguage lang, Storage s,
                  const std::string& material, const analysis::ShadingPoint& p) {
  return fmt::format("{} {} {} {} {} n·v {:g} roughness {:g}", fresnel::model_spec(m).name,
                     analysis::lighting_name(l), lang == ShaderLanguage::Glsl ? "glsl" : "hlsl",
                     storage_name(s), material, p.nov, p.roughness);
}

// Runs one (model, lighting, language, storage) for every material; adds to `worst`.
void run_one(fresnel::Model m, Lighting l, ShaderLanguage lang, Storage storage,
             const std::vector<Texture>& textures, Worst& worst) {
  const auto& f = fixture();
  std::vector<float> inputs;
  std::vector<Expected> want;
  for (size_t i = 0; i < f.studies.size(); ++i) {
    const auto& params = f.studies[i].result(m).derived;
    for (const auto& p : f.points) append_inputs(inputs, m, p.nov, p.roughness, params);
    want.push_back(expected(m, l, i, params, storage));
  }
  // What `fresnel-lab shader MODEL --lang L --lighting L --size N` prints, N the tables' size.
  analysis::ShaderRequest request;
  request.model = fresnel::model_spec(m).name;
  request.lang = lang == ShaderLanguage::Glsl ? "glsl" : "hlsl";
  request.lighting = analysis::lighting_name(l);
  if (!textures.empty()) request.size = textures.front().width;
  const std::string include = analysis::shader_text(request);
  const auto got = run_kernel(device(), m, l, lang, include, inputs, textures, storage);
  for (size_t i = 0; i < f.studies.size(); ++i)
    for (size_t k = 0; k < f.points.size(); ++k) {
      const auto& g = got[i * f.points.size() + k];
      const auto& e = want[i];
      color::Rgb rgb{g[0], g[1], g[2]};
      const std::string at =
          where(m, l, lang, storage, f.set.materials[i].material.name, f.points[k]);
      double diff = 0;
      for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(rgb[c] - e.rgb[k][c]));
      EXPECT_LE(diff, tolerance(storage)) << at;
      worst.add_rgb(diff, at);
      const double dde = std::abs(f.de00(e.truth[k], rgb) - e.de00[k]);
      EXPECT_LE(dde, kDe00Tolerance) << at;
      worst.add_de00(dde, at);
    }
}

// Every model × lighting (punctual, ibl, area) × language (GLSL, HLSL through glslang's HLSL front
// end) × table storage (half, float; punctual reads no table), as `fresnel-lab shader` emits it.
TEST(VulkanShaders, EveryModelLightingLanguageAndStorage) {
  ASSERT_NO_THROW(device());
  int runs = 0;
  std::map<Storage, Worst> worst;
  for (const auto& spec : fresnel::model_specs())
    for (Lighting l : {Lighting::Punctual, Lighting::Ibl, Lighting::Area}) {
      std::vector<Texture> textures;
      ASSERT_NO_THROW(textures = lighting_textures(spec.model, l, FL_VK_TABLES))
          << "the tables `lut dfg` and `lut ltc` write (CTest fixture Vulkan.tables)";
      for (ShaderLanguage lang : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl})
        for (Storage s : {Storage::Half, Storage::Float}) {
          if (l == Lighting::Punctual && s == Storage::Half) continue;
          SCOPED_TRACE(where(spec.model, l, lang, s, "", {}));
          run_one(spec.model, l, lang, s, textures, worst[s]);
          ++runs;
        }
    }
  std::printf(
      "%d runs (%zu models x 3 lightings x 2 languages, ibl/area x 2 storages), %zu "
      "materials x %zu points each\n",
      runs, fresnel::model_specs().size(), fixture().studies.size(), fixture().points.size());
  for (const auto& [s, w] : worst)
    std::printf(
        "%s: largest |driver - CPU model| %.3g (%s); largest ΔE2000 "
        "difference from lut-accuracy's %.3g (%s)\n",
        s == Storage::Half ? "half tables" : "float tables and punctual", w.rgb, w.rgb_at.c_str(),
        w.de00, w.de00_at.c_str());
}

}  // namespace
}  // namespace fl::test::vk
