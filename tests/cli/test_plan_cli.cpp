// The `plan` and `speed` commands through the CLI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "documents/plan_report.h"
#include "fresnel/registered_models.h"
#include "test_util.h"

namespace fl {
namespace {

TEST(PlanCli, JsonShapeAndHelp) {
  const auto r = test::run_command(test::cli() + " -q plan '" FL_EXAMPLES_DIR
                                                 "/scene_metals.yaml' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* key :
       {"\"materials\": [", "\"luts\": [", "\"material\": ", "\"model\": ", "\"params\": {",
        "\"rms_de00\": {\"ibl\": ", "\"error_used\": {\"lighting\": ", "\"gpu_instructions\": ",
        "\"cpu_ns_per_eval\": ", "\"f_avg\": [", "\"scene_shader\": {\"option\": ",
        "\"failing\": [", "\"scene_options\": [", "\"dominated_by\": "})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  EXPECT_EQ(test::run_command(test::cli() + " plan --help").status, 0);
  EXPECT_EQ(test::run_command(test::cli() + " speed --help").status, 0);
}

// The scenes of examples/ and three more: all dielectrics; metals at a budget of 0.3; mirrors and
// fully rough materials (roughness 0 and 1).
std::vector<std::string> property_scenes(const test::TempDir& dir) {
  std::vector<std::string> scenes;
  for (const auto& e : std::filesystem::directory_iterator(FL_EXAMPLES_DIR))
    if (e.path().extension() == ".yaml") scenes.push_back(e.path().string());
  std::sort(scenes.begin(), scenes.end());
  scenes.push_back(dir.file("dielectrics.yaml",
                            "materials: [glass_bk7, water, acrylic, diamond, ruby, quartz]\n"
                            "lighting: [punctual, ibl, area]\n"));
  scenes.push_back(dir.file("metals_0.3.yaml",
                            "materials: [gold, silver, copper, aluminum, chromium, iron]\n"
                            "max_de00: 0.3\nlighting: [ibl, area]\n"));
  scenes.push_back(dir.file("mirrors.yaml",
                            "materials:\n  - {name: silver, roughness: 0}\n"
                            "  - {name: glass_bk7, roughness: [0, 1]}\n"
                            "  - {name: gold, roughness: 1, group: trim}\n"
                            "  - {name: water, roughness: 0, group: trim}\n"
                            "lighting: [ibl, area]\n"));
  return scenes;
}

// The cost tuple as docs/commands.md states it: instructions, fetches, table bytes, variants;
// "unmeasured" after any number.
std::vector<double> cost_of(const nlohmann::json& o) {
  const auto count = [](const nlohmann::json& v) { return v.is_number() ? v.get<double>() : 1e18; };
  return {count(o["gpu_instructions"]), count(o["texture_fetches"]), o["table_bytes"].get<double>(),
          o["shader_variants"].get<double>()};
}
bool dominates(const nlohmann::json& a, const nlohmann::json& b) {
  const auto ca = cost_of(a), cb = cost_of(b);
  const double wa = a["worst_de00"], wb = b["worst_de00"];
  return ca <= cb && wa <= wb && (ca < cb || wa < wb);
}

// Over the JSON of every scene: the chosen option is listed and no listed option dominates it; it
// meets the budget whenever a listed option does; every option's dominated_by names an option
// that dominates it, and an option marked undominated is dominated by none.
TEST(PlanCli, ChosenOptionIsOnTheFrontOfEveryScene) {
  test::TempDir dir;
  for (const auto& scene : property_scenes(dir)) {
    const auto r = test::run_command(test::cli() + " -q plan '" + scene + "' --format json");
    ASSERT_EQ(r.status, 0) << scene << ": " << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    const auto& options = doc["scene_options"];
    ASSERT_FALSE(options.empty()) << scene;
    const std::string chosen_name = doc["scene_shader"]["option"];
    const nlohmann::json* chosen = nullptr;
    bool any_meets = false;
    for (const auto& o : options) {
      if (o["name"] == chosen_name) chosen = &o;
      any_meets = any_meets || o["meets_every_budget"].get<bool>();
    }
    ASSERT_NE(chosen, nullptr) << scene;
    EXPECT_TRUE((*chosen)["dominated_by"].is_null()) << scene;
    EXPECT_EQ((*chosen)["meets_every_budget"].get<bool>(), any_meets) << scene;
    for (const auto& o : options) {
      EXPECT_FALSE(dominates(o, *chosen)) << scene << ": " << o["name"] << " over " << chosen_name;
      bool dominated = false;
      for (const auto& q : options) dominated = dominated || dominates(q, o);
      EXPECT_EQ(dominated, !o["dominated_by"].is_null()) << scene << ": " << o["name"];
      if (o["dominated_by"].is_null()) continue;
      for (const auto& q : options)
        if (q["name"] == o["dominated_by"]) EXPECT_TRUE(dominates(q, o)) << scene << o["name"];
    }
    std::printf("%s: %s, %s instructions, worst %.3f, %zu options\n", scene.c_str(),
                chosen_name.c_str(), (*chosen)["gpu_instructions"].dump().c_str(),
                (*chosen)["worst_de00"].get<double>(), options.size());
  }
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The code inside an empty compute shader compiles (GLSL, or HLSL through glslang's HLSL front end)
// and its SPIR-V validates.
void expect_compiles(const std::string& code, bool hlsl, const std::string& what) {
  test::TempDir dir;
  const std::string src =
      dir.file(hlsl ? "s.hlsl" : "s.comp",
               hlsl ? code + "\n[numthreads(1, 1, 1)] void main() {}\n"
                    : "#version 450\nlayout(local_size_x = 1) in;\n" + code + "\nvoid main() {}\n");
  const auto c = test::run_command(
      std::string("glslangValidator -V ") + (hlsl ? "-D -S comp -e main " : "") + "'" + src +
      "' -o '" + dir.path() + "/s.spv' > /dev/null && spirv-val '" + dir.path() + "/s.spv'");
  EXPECT_EQ(c.status, 0) << what << "\n" << c.out << c.err << "\n" << code;
}

// `plan --shader` for every example scene, in GLSL and HLSL: each group's variant (selected by its
// macro) compiles inside an empty compute shader and its SPIR-V validates.
TEST(PlanCli, SceneShadersCompileAndValidate) {
  ASSERT_EQ(
      test::run_command("command -v glslangValidator >/dev/null && command -v spirv-val >/dev/null")
          .status,
      0)
      << "glslang-tools and spirv-tools (scripts/setup.sh)";
  for (const char* scene : {"scene_metals", "scene_ibl", "scene_area", "scene_punctual"}) {
    for (const char* lang : {"glsl", "hlsl"}) {
      const auto r = test::run_command(test::cli() + " -q plan '" FL_EXAMPLES_DIR "/" + scene +
                                       ".yaml' --shader --lang " + lang);
      ASSERT_EQ(r.status, 0) << scene << ": " << r.err;
      EXPECT_NE(r.out.find("fresnel_"), std::string::npos) << scene;
      const bool hlsl = std::string(lang) == "hlsl";
      std::vector<std::string> macros;
      for (size_t at = r.out.find("#ifdef "); at != std::string::npos;
           at = r.out.find("#ifdef ", at + 1))
        macros.push_back(r.out.substr(at + 7, r.out.find('\n', at) - at - 7));
      if (macros.empty()) macros.push_back("");
      for (const auto& macro : macros) {
        const std::string define = macro.empty() ? "" : "#define " + macro + "\n";
        expect_compiles(define + r.out, hlsl, std::string(scene) + " " + lang + " " + macro);
      }
    }
  }
}

// A split's --shader output: one variant per group behind its macro, each compiling alone in GLSL
// and HLSL; a mirror's group carries the model's function at n·v.
TEST(PlanCli, SplitVariantsCompileAndValidate) {
  using analysis::PlanChoice;
  const auto schlick = fresnel::model_from_name("schlick").model;
  const auto f82 = fresnel::model_from_name("f82").model;
  analysis::Plan p;
  p.scene.path = "hand.yaml";
  p.scene.ibl = p.scene.area = true;
  p.scene.materials = {{"gold", 2, {0.5}, ""}, {"glass", 3, {0.0}, ""}};
  analysis::SceneOption o;
  o.name = "metal: schlick, dielectric: f82";
  o.groups = {{"metal", schlick, {0}}, {"dielectric", f82, {1}}};
  PlanChoice gold, glass;
  gold.material = "Gold", gold.model = schlick, gold.params = {0.9, 0.7, 0.4};
  glass.material = "Glass", glass.model = f82, glass.params = {0.04, 0.5, 0.04, 0.5, 0.04, 0.5};
  glass.roughness = {0.0};
  o.materials = {gold, glass};
  p.scene_options = {o};
  for (const auto lang : {analysis::ShaderLanguage::Glsl, analysis::ShaderLanguage::Hlsl}) {
    analysis::ShaderDocument doc;
    doc.lang = lang;
    const std::string code = documents::plan_shader(p, doc);
    EXPECT_NE(code.find("#ifdef FRESNEL_GROUP_METAL"), std::string::npos);
    EXPECT_NE(code.find("#ifdef FRESNEL_GROUP_DIELECTRIC"), std::string::npos);
    EXPECT_NE(code.find("fresnel_f82("), std::string::npos);      // the mirror's F(n·v)
    EXPECT_EQ(code.find("fresnel_schlick("), std::string::npos);  // no mirror among the metals
    for (const char* macro : {"FRESNEL_GROUP_METAL", "FRESNEL_GROUP_DIELECTRIC"})
      expect_compiles(std::string("#define ") + macro + "\n" + code,
                      lang == analysis::ShaderLanguage::Hlsl, macro);
  }
}

// `plan --out DIR` for every example scene: the folder holds the include of each group, the tables
// the plan lists, materials.json, README.md, plan.md, plan.json and pareto.svg; every include
// compiles as GLSL and HLSL and validates. A second run, the folder named with a trailing slash,
// replaces it.
TEST(PlanCli, OutFolderForEveryExampleScene) {
  test::TempDir dir;
  bool checked_slash = false;
  for (const auto& e : std::filesystem::directory_iterator(FL_EXAMPLES_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    const std::string out = dir.path() + "/" + e.path().stem().string();
    const auto r =
        test::run_command(test::cli() + " -q plan '" + e.path().string() + "' --out '" + out + "'");
    ASSERT_EQ(r.status, 0) << e.path() << ": " << r.err;
    for (const char* f :
         {"README.md", "materials.json", "reference.csv", "plan.md", "plan.json", "pareto.svg"})
      EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << e.path() << " " << f;
    const auto plan = nlohmann::json::parse(slurp(out + "/plan.json"));
    for (const auto& lut : plan["scene_shader"]["luts"])
      EXPECT_TRUE(std::filesystem::exists(out + "/" + lut["file"].get<std::string>()))
          << e.path() << " " << lut["file"];
    int includes = 0;
    for (const auto& f : std::filesystem::directory_iterator(out)) {
      const auto ext = f.path().extension().string();
      if (ext != ".glsl" && ext != ".hlsl") continue;
      ++includes;
      expect_compiles(slurp(f.path().string()), ext == ".hlsl", f.path().string());
    }
    EXPECT_GE(includes, 2) << e.path();
    if (checked_slash) continue;
    // "DIR/" is DIR, an existing plan folder is written again: the path, once.
    checked_slash = true;
    const auto again = test::run_command(test::cli() + " -q plan '" + e.path().string() +
                                         "' --out '" + out + "/'");
    EXPECT_EQ(again.status, 0) << again.err;
    EXPECT_TRUE(std::filesystem::exists(out + "/README.md"));
  }
  EXPECT_TRUE(checked_slash);
}

}  // namespace
}  // namespace fl
