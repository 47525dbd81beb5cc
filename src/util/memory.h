#pragma once
// The heap on transparent huge pages: fewer, larger page faults for every command.

namespace fl {

// Asks Linux to back the heap's memory with transparent huge pages (2 MB) where the kernel offers
// them on request (/sys/kernel/mm/transparent_hugepage/enabled "madvise" or "always"), as glibc's
// tunable glibc.malloc.hugetlb=1 would. A page fault is costly on the virtual machines these jobs
// run on (about 14 µs of system time each here): reproduce took about 4,000 of them, 2,500 with
// huge pages, and 7 % less CPU. Call it first in main, before any thread starts; a no-op under the
// address sanitizer, whose allocator is not glibc's. Each thread of parallel_for then asks the same
// for its own malloc arena (huge_pages_for_this_thread).
void use_huge_pages_for_heap();

// Whether use_huge_pages_for_heap asked for huge pages (it does nothing under the address sanitizer).
bool huge_pages_requested();

// The calling thread's malloc arena on huge pages (parallel_for calls it on each worker once
// use_huge_pages_for_heap has been called).
void huge_pages_for_this_thread();

}  // namespace fl
