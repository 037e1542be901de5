#pragma once
// Start-up memory policy of the mrsim process (docs/performance.md, "Page faults").
#include <cstddef>

namespace mrsim {

/// Grows the process heap by `bytes` once, asks the kernel to back that range with
/// transparent huge pages (madvise MADV_HUGEPAGE; the host's "madvise" THP mode honours it),
/// and keeps arrays up to 32 MiB on the heap, reused after they are freed rather than unmapped
/// and faulted in again. On a virtual machine a 4 KiB page fault costs several microseconds:
/// liver_probe's set-up faulted in about 6 000 of them. Untouched pages of the range cost no
/// memory. Returns the bytes advised (0 without glibc, under the sanitizers, which own the
/// allocator, or when the heap could not grow). Call once, first thing in main().
std::size_t reserve_huge_page_heap(std::size_t bytes);

}  // namespace mrsim
