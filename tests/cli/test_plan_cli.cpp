// The `plan` and `speed` commands through the CLI.
#include <gtest/gtest.h>

#include <string>

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
        "\"cpu_ns_per_eval\": ", "\"f_avg\": [",
        "\"scene_shader\": {\"model\": ", "\"failing\": ["})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  EXPECT_EQ(test::run_command(test::cli() + " plan --help").status, 0);
  EXPECT_EQ(test::run_command(test::cli() + " speed --help").status, 0);
}

// `plan --shader` for every example scene, in GLSL and HLSL: the code compiles (inside an empty
// compute shader) and its SPIR-V validates.
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
      test::TempDir dir;
      const bool hlsl = std::string(lang) == "hlsl";
      const std::string src = dir.file(
          hlsl ? "s.hlsl" : "s.comp",
          hlsl ? r.out + "\n[numthreads(1, 1, 1)] void main() {}\n"
               : "#version 450\nlayout(local_size_x = 1) in;\n" + r.out + "\nvoid main() {}\n");
      const auto c = test::run_command(
          std::string("glslangValidator -V ") + (hlsl ? "-D -S comp -e main " : "") + "'" + src +
          "' -o '" + dir.path() + "/s.spv' > /dev/null && spirv-val '" + dir.path() + "/s.spv'");
      EXPECT_EQ(c.status, 0) << scene << " " << lang << "\n" << c.out << c.err << "\n" << r.out;
    }
  }
}

}  // namespace
}  // namespace fl
