#include "core/processor_count.hpp"

#include <unistd.h>

#include <algorithm>

namespace mrsim {

int online_processors() {
  // sysconf counts them inside glibc (its own get_nprocs, not the one below). At least one:
  // thread pools size their per-thread storage with it, and sysconf answers -1 on failure.
  static const int count = static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  return count;
}

}  // namespace mrsim

extern "C" int get_nprocs(void) { return mrsim::online_processors(); }
