#include "util/parallel.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

#include <exception>
#include <vector>

namespace fl {

void parallel_for(std::size_t n, const std::function<void(std::size_t)>& body, int threads) {
  if (n == 0) return;
  // One task per index: the bodies are long (a material, a row of cells or pixels).
  const auto loop = [&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, 1),
        [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
        },
        tbb::simple_partitioner());
  };
  // More threads than the machine has would only make oneTBB warn on stderr.
  const int machine = tbb::info::default_concurrency();
  if (threads == 1 || machine == 1) {
    for (std::size_t i = 0; i < n; ++i) body(i);
  } else if (threads > 1 && threads < machine) {
    tbb::task_arena arena(threads);
    arena.execute(loop);
  } else {
    loop();
  }
}

void parallel_for_all(std::size_t n, const std::function<void(std::size_t)>& body, int threads) {
  std::vector<std::exception_ptr> errors(n);
  parallel_for(
      n,
      [&](std::size_t i) {
        try {
          body(i);
        } catch (...) {
          errors[i] = std::current_exception();
        }
      },
      threads);
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

void ProgressCounter::add(int units) {
  std::lock_guard lock(mutex_);
  done_ += units;
  if (report_) report_(done_, total_);
}

}  // namespace fl
