// Every example scene's `plan --out` folder run on the Vulkan device as an engine would use it:
// each include (GLSL and HLSL) with the folder's tables (RGBA16F and RGBA32F, linear, clamp to
// edge) and each material's parameters from materials.json, at every row of reference.csv, against
// the row's expected RGB (the CPU engine model) and its ΔE2000 against the truth.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "analysis/plan/reference.h"
#include "color/lab.h"
#include "csv_reader.h"
#include "fresnel/registered_models.h"
#include "vulkan/shader_kernel.h"

namespace fl::test::vk {
namespace {

using analysis::Lighting;
using analysis::ShaderLanguage;

// The tolerances of shader_kernel.h: the driver against the CPU model (reference.csv's engine
// values, from the texels as the folder's files store them), and the ΔE2000 against the truth
// recomputed from the driver's RGB against reference.csv's (which rounds it to 4 decimals). Files
// of floats uploaded as RGBA16F are rounded by the upload, which reference.csv does not model: the
// RGB is held to kHalfTolerance and the ΔE2000 (up to about 0.009 apart) reported, not checked.

struct PlanMaterial {
  std::string name, include;
  fresnel::Model model;
  std::vector<double> params;
};

std::map<std::string, PlanMaterial> plan_materials(const std::string& folder) {
  const auto doc = nlohmann::json::parse(read_text_file(folder + "/materials.json"));
  std::map<std::string, PlanMaterial> out;
  for (const auto& m : doc["materials"]) {
    const auto& spec = fresnel::model_from_name(m["model"].get<std::string>());
    PlanMaterial pm{m["material"], m["include"], spec.model, {}};
    for (const auto& name : spec.param_names()) pm.params.push_back(m["params"][name]);
    out.emplace(pm.name, pm);
  }
  return out;
}

// One dispatch: the rows of reference.csv one include's function is checked at.
struct Batch {
  const PlanMaterial* material = nullptr;  // any of the include's: its model
  Lighting lighting = Lighting::Punctual;  // the function's (punctual: the model at n·v)
  std::vector<float> inputs;
  std::vector<const CsvRecord*> rows;
};

// Rows grouped by (include, function).
std::map<std::pair<std::string, std::string>, Batch> batches(
    const std::map<std::string, PlanMaterial>& materials, const std::vector<CsvRecord>& rows) {
  std::map<std::pair<std::string, std::string>, Batch> out;
  for (const auto& r : rows) {
    const auto& m = materials.at(r.at("material"));
    const bool at_nov =
        r.at("function") == analysis::shader_function_name(m.model, Lighting::Punctual);
    auto& b = out[{m.include, r.at("function")}];
    b.material = &m;
    b.lighting = at_nov ? Lighting::Punctual : analysis::lighting_from_name(r.at("lighting"));
    append_inputs(b.inputs, m.model, std::stod(r.at("nov")),
                  at_nov ? 0.0 : std::stod(r.at("roughness")), m.params);
    b.rows.push_back(&r);
  }
  return out;
}

color::Rgb row_rgb(const CsvRecord& r, const std::string& what) {
  return {std::stod(r.at(what + "_r")), std::stod(r.at(what + "_g")), std::stod(r.at(what + "_b"))};
}

struct Totals {
  int runs = 0;
  double rgb_half = 0, rgb_float = 0;  // by upload storage
  double de00 = 0, de00_rounded = 0;   // the latter: float files uploaded as half
};

void check_batch(const analysis::Context& ctx, const std::string& folder, const Batch& b,
                 const std::string& include, ShaderLanguage lang, Storage storage, bool files_half,
                 Totals& t) {
  const auto textures = lighting_textures(b.material->model, b.lighting, folder);
  const std::string file =
      folder + "/" +
      (lang == ShaderLanguage::Glsl
           ? include
           : std::filesystem::path(include).replace_extension(".hlsl").string());
  const auto got = run_kernel(shared_device(), b.material->model, b.lighting, lang,
                              read_text_file(file), b.inputs, textures, storage);
  ++t.runs;
  for (size_t k = 0; k < b.rows.size(); ++k) {
    const auto& r = *b.rows[k];
    const color::Rgb rgb{got[k][0], got[k][1], got[k][2]}, want = row_rgb(r, "engine");
    double diff = 0;
    for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(rgb[c] - want[c]));
    const std::string at = fmt::format("{} {} {} n·v {} roughness {}", file, storage_name(storage),
                                       r.at("material"), r.at("nov"), r.at("roughness"));
    EXPECT_LE(diff, storage == Storage::Half ? kHalfTolerance : kFloatTolerance) << at;
    const double de00 = color::ciede2000(ctx.rgb_to_lab(row_rgb(r, "truth")), ctx.rgb_to_lab(rgb));
    const double dde = std::abs(de00 - std::stod(r.at("de00")));
    if (storage == Storage::Float || files_half) {
      EXPECT_LE(dde, kDe00Tolerance) << at;
      t.de00 = std::max(t.de00, dde);
    } else {
      t.de00_rounded = std::max(t.de00_rounded, dde);
    }
    double& rgb_max = storage == Storage::Half ? t.rgb_half : t.rgb_float;
    rgb_max = std::max(rgb_max, diff);
  }
}

TEST(VulkanPlans, EveryExampleSceneIncludeMatchesItsReference) {
  ASSERT_NO_THROW(shared_device());
  const analysis::Context ctx{[] {
    analysis::Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  int runs = 0;
  for (const auto& e : std::filesystem::directory_iterator(FL_EXAMPLES_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    const std::string folder = std::string(FL_VK_PLANS) + "/" + e.path().stem().string();
    ASSERT_TRUE(std::filesystem::exists(folder + "/reference.csv"))
        << folder << ": made by the CTest fixture Vulkan.plan_" << e.path().stem().string();
    const auto materials = plan_materials(folder);
    const auto plan = nlohmann::json::parse(read_text_file(folder + "/plan.json"));
    const auto& shader = plan["scene_shader"];
    const bool has_tables = shader.contains("lut_tables");
    const bool files_half = has_tables && shader["lut_tables"]["storage"] == "half";
    const std::string tables = has_tables
                                   ? fmt::format("{}² {}", shader["lut_tables"]["size"].get<int>(),
                                                 shader["lut_tables"]["storage"].get<std::string>())
                                   : "none";
    const auto rows = csv_records(read_text_file(folder + "/reference.csv"));
    EXPECT_FALSE(rows.empty()) << folder;
    Totals scene;
    for (const auto& [key, b] : batches(materials, rows))
      for (ShaderLanguage lang : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl})
        for (Storage s : {Storage::Half, Storage::Float}) {
          if (b.lighting == Lighting::Punctual && s == Storage::Half) continue;
          check_batch(ctx, folder, b, key.first, lang, s, files_half, scene);
        }
    std::printf(
        "%s: tables %s, reference.csv %zu rows, %d runs; largest |driver - reference| %.3g "
        "(RGBA32F), %.3g (RGBA16F); ΔE2000 difference %.3g (%.3g float files as RGBA16F)\n",
        e.path().filename().c_str(), tables.c_str(), rows.size(), scene.runs, scene.rgb_float,
        scene.rgb_half, scene.de00, scene.de00_rounded);
    runs += scene.runs;
  }
  EXPECT_GT(runs, 0);
}

}  // namespace
}  // namespace fl::test::vk
