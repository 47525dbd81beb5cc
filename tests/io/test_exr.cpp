// OpenEXR output (io/exr.h): round trip of pixels and attributes, atomic write.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "io/exr.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::io {
namespace {

TEST(Exr, RoundTripKeepsFloatsAndAttributes) {
  test::TempDir tmp;
  ExrImage img;
  img.width = 3;
  img.height = 2;
  img.channels = {"R", "G"};
  for (int k = 0; k < 12; ++k) img.pixels.push_back(0.1f * k - 0.3f);
  img.string_attributes = {{"fresnelLab:xAxis", "nov"}};
  img.float_attributes = {{"fresnelLab:xMax", 0.75f}};
  const auto path = tmp.path() + "/t.exr";
  write_exr_atomic(path, img);
  const auto back = read_exr(path);
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  // OpenEXR lists channels alphabetically: G, R.
  ASSERT_EQ(back.channels, (std::vector<std::string>{"G", "R"}));
  for (int p = 0; p < 6; ++p) {
    EXPECT_EQ(back.pixels[2 * p + 0], img.pixels[2 * p + 1]);
    EXPECT_EQ(back.pixels[2 * p + 1], img.pixels[2 * p + 0]);
  }
  const auto has_string = std::find(back.string_attributes.begin(), back.string_attributes.end(),
                                    std::pair<std::string, std::string>{"fresnelLab:xAxis", "nov"});
  EXPECT_NE(has_string, back.string_attributes.end());
  const auto has_float = std::find(back.float_attributes.begin(), back.float_attributes.end(),
                                   std::pair<std::string, float>{"fresnelLab:xMax", 0.75f});
  EXPECT_NE(has_float, back.float_attributes.end());
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(tmp.path()), {}),
            1);  // no temporary left
}

// Chromaticities with a NaN (or all NaN) name no colour space: refused, not matched to one.
TEST(Exr, NanChromaticitiesAreRefused) {
  test::TempDir tmp;
  ExrImage img;
  img.width = 2;
  img.height = 1;
  img.channels = {"B", "G", "R"};
  img.pixels.assign(6, 0.5f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const auto& c :
       {std::array<float, 8>{nan, nan, nan, nan, nan, nan, nan, nan},
        std::array<float, 8>{0.64f, 0.33f, 0.3f, 0.6f, 0.15f, 0.06f, nan, 0.329f}}) {
    img.chromaticities = c;
    const auto path = tmp.path() + "/nan.exr";
    write_exr_atomic(path, img);
    try {
      read_exr(path);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("the chromaticities attribute holds a NaN"),
                std::string::npos)
          << e.what();
    }
  }
  img.chromaticities =
      std::array<float, 8>{0.64f, 0.33f, 0.3f, 0.6f, 0.15f, 0.06f, 0.3127f, 0.329f};
  write_exr_atomic(tmp.path() + "/ok.exr", img);
  EXPECT_EQ(read_exr(tmp.path() + "/ok.exr").chromaticities, img.chromaticities);
}

}  // namespace
}  // namespace fl::io
