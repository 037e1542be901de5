#include "core/processor_count.hpp"

#include <unistd.h>

namespace mrsim {

int online_processors() {
  // sysconf counts them inside glibc (its own get_nprocs, not the one below).
  static const int count = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  return count;
}

}  // namespace mrsim

extern "C" int get_nprocs(void) { return mrsim::online_processors(); }
