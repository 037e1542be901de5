#include "core/huge_page_heap.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace mrsim {
namespace {

// The VmFlags line of the mapping that holds `address` in /proc/self/smaps ("" if none).
std::string vm_flags_of(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo <= a && a < hi;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

TEST(HugePageHeap, LargeArraysComeFromTheAdvisedHeap) {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
  GTEST_SKIP() << "the sanitizers own the allocator";
#else
  const std::size_t advised = reserve_huge_page_heap(std::size_t{16} << 20);
  ASSERT_GE(advised, std::size_t{8} << 20) << "most of the 16 MiB asked is advised";
  ASSERT_EQ(advised % (std::size_t{2} << 20), 0u) << "whole 2 MiB pages";
  // A 4 MiB array, which glibc would map on its own by default, now lies on the heap, below
  // the break, in a mapping flagged for huge pages ("hg").
  void* array = std::malloc(std::size_t{4} << 20);
  ASSERT_NE(array, nullptr);
  EXPECT_LT(reinterpret_cast<std::uintptr_t>(array), reinterpret_cast<std::uintptr_t>(sbrk(0)));
  const std::string flags = vm_flags_of(static_cast<char*>(array) + (std::size_t{2} << 20));
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  // It starts where the advised pages do (within the 4 KiB page below the first 2 MiB boundary),
  // not in the part of the heap below them, which would fault in 4 KiB pages first.
  const auto at = reinterpret_cast<std::uintptr_t>(array);
  const std::uintptr_t huge = std::uintptr_t{2} << 20;
  EXPECT_LT(((at + huge - 1) & ~(huge - 1)) - at, std::uintptr_t{4096}) << std::hex << at;
  std::free(array);
#endif
}

}  // namespace
}  // namespace mrsim
