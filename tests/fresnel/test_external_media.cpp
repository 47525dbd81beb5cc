// F0 re-expressed for an external medium of real index η_E (fresnel/media.h).
#include <gtest/gtest.h>

#include <cmath>

#include "fresnel/media.h"

namespace fl::fresnel {
namespace {

constexpr double kExact = 1e-12;

TEST(Media, SymmetricAdjustmentIsExactForDielectricsAtNormalIncidence) {
  for (double n : {1.33, 1.5, 2.417})
    for (double eta_e : {1.0, 1.333, 1.6, 2.0, 2.417, 3.0}) {
      const double f0 = std::pow((n - 1) / (n + 1), 2),
                   expected = std::pow((n - eta_e) / (n + eta_e), 2);
      EXPECT_NEAR(f0_in_medium_symmetric(f0, eta_e), expected, kExact) << n << " in " << eta_e;
    }
  for (double f0 : {0.04, 0.5, 0.95}) EXPECT_NEAR(f0_in_medium_metal(f0, 1.0), f0, kExact);
}

}  // namespace
}  // namespace fl::fresnel
