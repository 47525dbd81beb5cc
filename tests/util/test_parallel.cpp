// fl::parallel_for and fl::ProgressCounter (src/util/).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "util/parallel.h"
#include "util/quantile.h"

namespace {

TEST(ParallelFor, CallsEveryIndexOnceForAnyThreadCount) {
  constexpr std::size_t kCount = 1000;
  for (const int threads : {0, 1, 2, 7}) {
    std::vector<std::atomic<int>> calls(kCount);
    fl::parallel_for(
        kCount, [&](std::size_t i) { ++calls[i]; }, threads);
    for (std::size_t i = 0; i < kCount; ++i)
      ASSERT_EQ(calls[i].load(), 1) << "index " << i << ", threads " << threads;
  }
  fl::parallel_for(0, [](std::size_t) { FAIL() << "called for an empty range"; });
}

TEST(ParallelFor, WorkerExceptionReachesTheCaller) {
  for (const int threads : {0, 1, 2}) {
    std::atomic<int> calls{0};
    try {
      fl::parallel_for(
          64,
          [&](std::size_t i) {
            ++calls;
            if (i == 5) throw std::invalid_argument("cell 5 failed");
          },
          threads);
      FAIL() << "no exception, threads " << threads;
    } catch (const std::invalid_argument& e) {
      EXPECT_STREQ(e.what(), "cell 5 failed");
    }
    EXPECT_GE(calls.load(), 1);
  }
}

TEST(ProgressCounter, ReportsIncreasingCountsUpToTheTotal) {
  std::vector<int> seen;
  fl::ProgressCounter done(
      [&](int d, int total) {
        EXPECT_EQ(total, 300);
        seen.push_back(d);
      },
      300);
  fl::parallel_for(
      100, [&](std::size_t) { done.add(3); }, 2);
  ASSERT_EQ(seen.size(), 100u);
  for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], static_cast<int>(3 * (k + 1)));
}

}  // namespace
