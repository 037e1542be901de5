#include "core/huge_page_heap.hpp"

#include <climits>
#include <cstdint>
#include <cstdlib>

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#define MRSIM_HUGE_PAGE_HEAP 1
#endif

namespace mrsim {

std::size_t reserve_huge_page_heap(std::size_t bytes) {
#ifdef MRSIM_HUGE_PAGE_HEAP
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;  // x86-64's PMD page
  constexpr int kHeapArrays = 32 << 20;                      // glibc's largest mmap threshold
  // Arrays below the threshold come from the heap (glibc would start mapping at 128 KiB), and
  // the heap's top is not handed back: a freed array's pages serve the next one.
  if (mallopt(M_MMAP_THRESHOLD, kHeapArrays) == 0 || mallopt(M_TRIM_THRESHOLD, 1 << 30) == 0)
    return 0;
  // The next growth of the heap adds `bytes` beyond what it is asked for (glibc's top pad), so
  // one small block brings the whole range; freed at once, the block goes back to the heap's
  // free top untouched (malloc writes only its header). Then the usual 128 KiB pad again.
  if (bytes > INT_MAX / 2 || mallopt(M_TOP_PAD, static_cast<int>(bytes)) == 0) return 0;
  const std::size_t block = kHuge;
  void* probe = std::malloc(block);
  if (probe == nullptr) return 0;
  const auto begin = (reinterpret_cast<std::uintptr_t>(probe) + kHuge - 1) & ~(kHuge - 1);
  const auto top = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const auto end = top & ~(kHuge - 1);
  // A block mapped on its own (the heap could not grow) lies beyond the break: leave it.
  const bool on_heap = reinterpret_cast<std::uintptr_t>(probe) < top;
  std::size_t advised = 0;
  if (on_heap && end > begin &&
      madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) == 0)
    advised = end - begin;
  // The probe's head, below the first 2 MiB boundary, stays allocated and is never touched: the
  // arrays that follow start on huge pages instead of faulting in up to 2 MiB of 4 KiB pages
  // first (about 500 faults, a tenth of a warm liver_probe set-up). Shrinking never moves a
  // block; what is cut off goes back to the heap's top.
  const std::size_t head = begin - reinterpret_cast<std::uintptr_t>(probe);
  void* kept = advised > 0 && head >= 64 ? std::realloc(probe, head - 32) : nullptr;
  if (kept != probe) std::free(kept ? kept : probe);
  mallopt(M_TOP_PAD, 128 << 10);
  return advised;
#else
  (void)bytes;
  return 0;
#endif
}

}  // namespace mrsim
