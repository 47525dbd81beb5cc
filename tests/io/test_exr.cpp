// OpenEXR output (io/exr.h): round trip of pixels and attributes, atomic write; a file OpenEXR
// writes with its data window far from the origin read back.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
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

// A data window 10⁹ rows below the origin, 60,000 pixels wide: the reader's slice is addressed
// from the window's corner, and a base pointer offset by it (10⁹ rows of 240,000 bytes) would
// leave the address space (the sanitized suite reports such an offset).
TEST(Exr, ADataWindowFarFromTheOriginIsRead) {
  test::TempDir tmp;
  const int width = 60000, top = 1000000000;
  const Imath::Box2i window({0, top}, {width - 1, top});
  Imf::Header header(Imath::Box2i({0, 0}, {width - 1, 0}), window);
  header.compression() = Imf::ZIP_COMPRESSION;
  std::vector<float> pixels(width);
  for (int x = 0; x < width; ++x) pixels[x] = 0.25f + 0.5f * static_cast<float>(x % 3);
  header.channels().insert("R", Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer fb;
  fb.insert("R", Imf::Slice::Make(Imf::FLOAT, pixels.data(), window, sizeof(float), 0));
  const auto path = tmp.path() + "/far.exr";
  {
    Imf::OutputFile out(path.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(1);
  }
  const auto back = read_exr(path);
  ASSERT_EQ(back.width, width);
  ASSERT_EQ(back.height, 1);
  EXPECT_EQ(back.pixels, pixels);
}

}  // namespace
}  // namespace fl::io
