// util/memory.h: the heap's memory marked for transparent huge pages, as the kernel reports it in
// /proc/self/smaps ("hg" among a mapping's VmFlags: MADV_HUGEPAGE was applied to it).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "util/memory.h"
#include "util/parallel.h"

namespace {

// Whether the kernel honours MADV_HUGEPAGE: transparent huge pages in "always" or "madvise" mode.
bool kernel_offers_huge_pages() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(in, line);
  return line.find("[always]") != std::string::npos || line.find("[madvise]") != std::string::npos;
}

// The VmFlags of the mapping holding `address`, from /proc/self/smaps.
std::string vm_flags_at(const void* address) {
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream in("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo <= a && a < hi;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

bool marked(const void* address) { return vm_flags_at(address).find(" hg") != std::string::npos; }

class HugePages : public ::testing::Test {
 protected:
  void SetUp() override {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "the address sanitizer's allocator is not glibc's";
#endif
    if (!kernel_offers_huge_pages()) GTEST_SKIP() << "no transparent huge pages on request in this kernel";
    fl::use_huge_pages_for_heap();
  }
};

TEST_F(HugePages, MainHeapIsMarked) {
  const std::unique_ptr<char[]> block(new char[100'000]);
  EXPECT_TRUE(marked(block.get())) << vm_flags_at(block.get());
}

// A block allocated on a worker of parallel_for lies in that thread's arena, marked as it joined.
TEST_F(HugePages, WorkerArenasAreMarked) {
  std::vector<std::string> flags(64);
  std::vector<bool> ok(64);
  fl::parallel_for(64, [&](size_t i) {
    const std::unique_ptr<char[]> block(new char[1000]);
    ok[i] = marked(block.get());
    flags[i] = vm_flags_at(block.get());
  });
  for (size_t i = 0; i < ok.size(); ++i) EXPECT_TRUE(ok[i]) << i << ": " << flags[i];
}

}  // namespace
