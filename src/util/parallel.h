#pragma once
// The one parallel loop of the project (oneTBB stays inside parallel.cpp), and a progress counter
// for work done on several threads.
#include <cstddef>
#include <functional>
#include <mutex>

namespace fl {

// Calls body(i) once for every i in [0, n), on up to `threads` threads (0: every hardware thread).
// Each call must write only its own results (slot i of an output), so the outcome does not depend
// on the number of threads or the schedule. When a call throws, the calls not yet started are
// skipped and the first exception is rethrown here once the running calls have finished.
void parallel_for(std::size_t n, const std::function<void(std::size_t)>& body, int threads = 0);

// parallel_for that makes every call, and when calls throw, rethrows the exception of the lowest i
// once all have finished: the same error whatever the schedule (the first bad file of a list).
void parallel_for_all(std::size_t n, const std::function<void(std::size_t)>& body, int threads = 0);

// Counts finished work from any thread and passes (done, total) to `report` after each add(),
// one call at a time, with done increasing.
class ProgressCounter {
 public:
  ProgressCounter(std::function<void(int done, int total)> report, int total, int done = 0)
      : report_(std::move(report)), total_(total), done_(done) {}
  void add(int units);

 private:
  std::function<void(int, int)> report_;
  int total_;
  int done_;
  std::mutex mutex_;
};

}  // namespace fl
