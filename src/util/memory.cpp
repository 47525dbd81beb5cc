#include "util/memory.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>

namespace fl {
namespace {

std::atomic<bool> requested{false};

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// glibc's HEAP_MAX_SIZE on 64-bit systems (2 × DEFAULT_MMAP_THRESHOLD_MAX): a thread's arena is one
// mapping of this size, aligned to it, grown in place.
constexpr std::uintptr_t kArenaHeap = std::uintptr_t{64} << 20;
// Each heap grows by at least this much, so a new stretch spans whole huge pages (2 MB) and the
// kernel can fault one in at once; 8 MB keeps the whole-database jobs' peak memory within 5 % of
// what it is without.
constexpr int kTopPad = 8 << 20;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kGlibcMalloc = false;
#else
constexpr bool kGlibcMalloc = true;
#endif

}  // namespace

void use_huge_pages_for_heap() {
  if (!kGlibcMalloc) return;
  mallopt(M_TOP_PAD, kTopPad);
  // Grow the main heap now (past its free top chunk), then mark it from the huge page holding its
  // first block up to the break: MADV_HUGEPAGE is a hint, and on a kernel without transparent huge
  // pages it fails and changes nothing.
  void* block = std::malloc(mallinfo2().keepcost + 4096);
  const std::uintptr_t lo = reinterpret_cast<std::uintptr_t>(block) & ~(kHugePage - 1);
  const std::uintptr_t hi = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (block && hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
  std::free(block);
  requested = true;
}

bool huge_pages_requested() { return requested; }

void huge_pages_for_this_thread() {
  // A block of this thread's arena lies in its heap mapping; marking the whole mapping covers its
  // later growth too. Were the block in the main heap (marked already), the range is part of it or
  // unmapped, and madvise then fails harmlessly.
  void* block = std::malloc(64);
  const std::uintptr_t base = reinterpret_cast<std::uintptr_t>(block) & ~(kArenaHeap - 1);
  madvise(reinterpret_cast<void*>(base), kArenaHeap, MADV_HUGEPAGE);
  std::free(block);
}

}  // namespace fl
