// The nearest-rank rule (Hyndman & Fan 1996, definition 1) on lists worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "util/quantile.h"

namespace {

// 1..20 shuffled: rank ⌈q·20⌉. p90 → rank 18; p99 → ⌈19.8⌉ = 20; median → rank 10; p5 → rank 1.
const std::vector<double> kTwenty = {7, 3,  19, 1, 12, 20, 5, 16, 9,  14,
                                     2, 18, 11, 6, 15, 4,  8, 17, 13, 10};

TEST(Quantile, NearestRankOnTwentyValues) {
  EXPECT_EQ(fl::quantile(kTwenty, 0.9), 18.0);
  EXPECT_EQ(fl::quantile(kTwenty, 0.99), 20.0);
  EXPECT_EQ(fl::quantile(kTwenty, 0.5), 10.0);
  EXPECT_EQ(fl::quantile(kTwenty, 0.05), 1.0);
  EXPECT_EQ(fl::quantile(kTwenty, 0.0), 1.0);
  EXPECT_EQ(fl::quantile(kTwenty, 1.0), 20.0);
  EXPECT_EQ(fl::median(kTwenty), 10.0);
}

// 0.29·100 is 28.999999999999996 in binary: the rank is still 29, not 30. p99 over 385 values is
// rank ⌈381.15⌉ = 382 (the 4th largest), where round(0.99·384) = 380 would take the 6th largest.
TEST(Quantile, RanksAtExactProductsAndTheLibraryCount) {
  std::vector<double> hundred;
  for (int i = 1; i <= 100; ++i) hundred.push_back(i);
  EXPECT_EQ(fl::quantile(hundred, 0.29), 29.0);
  std::vector<double> v;
  for (int i = 1; i <= 385; ++i) v.push_back(i);
  EXPECT_EQ(fl::quantile(v, 0.99), 382.0);
  EXPECT_EQ(fl::quantile(v, 0.9), 347.0);  // ⌈346.5⌉
  EXPECT_EQ(fl::median(v), 193.0);
}

TEST(Quantile, EvenCountMedianIsTheLowerMiddleAndSampleMedianTheMean) {
  EXPECT_EQ(fl::median({4.0, 1.0, 3.0, 2.0}), 2.0);
  EXPECT_EQ(fl::sample_median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(fl::sample_median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(fl::median({-7.0}), -7.0);
  EXPECT_TRUE(std::isnan(fl::median({})));
  EXPECT_TRUE(std::isnan(fl::sample_median({})));
}

TEST(Quantile, LargestIndicesInOrderWithTiesByIndex) {
  const std::vector<double> v = {0.5, 3.0, 1.0, 3.0, 2.0};
  EXPECT_EQ(fl::largest_indices(v, 3), (std::vector<std::size_t>{1, 3, 4}));
  EXPECT_EQ(fl::largest_indices(v, 9).size(), 5u);
}

}  // namespace
