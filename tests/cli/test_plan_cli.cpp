// The `plan` and `speed` commands through the CLI.
#include <gtest/gtest.h>

#include <string>

#include "test_util.h"

namespace fl {
namespace {

TEST(PlanCli, JsonShapeAndHelp) {
  const auto r = test::run_command(test::cli() + " -q plan '" FL_EXAMPLES_DIR "/scene_metals.yaml' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* key : {"\"materials\": [", "\"luts\": [", "\"material\": ", "\"model\": ", "\"params\": {",
                          "\"rms_de00\": {\"ibl\": ", "\"error_used\": {\"lighting\": ", "\"gpu_instructions\": ",
                          "\"cpu_ns_per_eval\": ", "\"f_avg\": [", "\"scene_shader\": {\"model\": ", "\"failing\": ["})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  EXPECT_EQ(test::run_command(test::cli() + " plan --help").status, 0);
  EXPECT_EQ(test::run_command(test::cli() + " speed --help").status, 0);
}

}  // namespace
}  // namespace fl
