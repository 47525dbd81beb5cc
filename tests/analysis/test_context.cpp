// The run's colour pipeline (analysis/context.h): reflectance spectrum → working-space RGB.
#include <gtest/gtest.h>

#include <vector>

#include "analysis/context.h"
#include "color/rgb_space.h"

namespace fl::analysis {
namespace {

using color::Lab;
using color::Rgb;

constexpr double kWhiteTolerance = 1e-6;

TEST(Pipeline, PerfectWhiteReflectorMapsToWorkingWhiteInEverySpace) {
  for (const auto& space : color::builtin_space_names())
    for (const char* illuminant : {"D60", "D65", "D50", "A", "E", "D7200"})
      for (const char* adaptation : {"bradford", "cat02"}) {
        Settings s;
        s.space = space;
        s.illuminant = illuminant;
        s.adaptation = adaptation;
        const Context ctx(s);
        const Rgb white = ctx.spectrum_to_rgb(std::vector<double>(ctx.grid().count, 1.0));
        EXPECT_NEAR(white.r, 1.0, kWhiteTolerance) << space << " " << illuminant << " " << adaptation;
        EXPECT_NEAR(white.g, 1.0, kWhiteTolerance) << space << " " << illuminant << " " << adaptation;
        EXPECT_NEAR(white.b, 1.0, kWhiteTolerance) << space << " " << illuminant << " " << adaptation;
        const Lab lab = ctx.rgb_to_lab(white);
        EXPECT_NEAR(lab.L, 100.0, 1e-4);
        EXPECT_NEAR(lab.a, 0.0, 1e-4);
        EXPECT_NEAR(lab.b, 0.0, 1e-4);
      }
}

}  // namespace
}  // namespace fl::analysis
