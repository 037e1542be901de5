// The processor count is read once per process (core/processor_count.hpp): asking
// std::thread::hardware_concurrency() again, as VTK does for every array range it computes, makes
// no more read system calls (counted by the kernel in /proc/self/io).
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <thread>

#include "core/processor_count.hpp"

namespace {

// syscr of /proc/self/io: the read system calls this process made so far (-1 if unavailable).
long read_syscalls() {
  std::ifstream io("/proc/self/io");
  std::string key;
  long value = -1;
  while (io >> key >> value)
    if (key == "syscr:") return value;
  return -1;
}

TEST(ProcessorCount, CountedOnceHardwareConcurrencyReadsNothing) {
  const int count = mrsim::online_processors();
  ASSERT_GE(count, 1);
  EXPECT_EQ(std::thread::hardware_concurrency(), static_cast<unsigned>(count));
  if (read_syscalls() < 0) GTEST_SKIP() << "no /proc/self/io";
  // The reads that reading /proc/self/io itself costs, between two readings with nothing between.
  const long a = read_syscalls(), b = read_syscalls();
  unsigned sum = 0;
  for (int i = 0; i < 50; ++i) sum += std::thread::hardware_concurrency();
  const long c = read_syscalls();
  EXPECT_EQ(sum, 50u * static_cast<unsigned>(count));
  EXPECT_EQ(c - b, b - a) << "hardware_concurrency() read the system's processor list again";
}

}  // namespace
