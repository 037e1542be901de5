#include "core/parallel.hpp"

#include <atomic>
#include <cstdlib>

namespace mrsim {
namespace {
// MRSIM_PARALLEL_THRESHOLD lets end-to-end tests force the threaded path on small meshes.
int initial_threshold() {
  if (const char* env = std::getenv("MRSIM_PARALLEL_THRESHOLD")) return std::atoi(env);
  return 8192;
}
std::atomic<int> g_threshold{initial_threshold()};
}  // namespace
int parallel_threshold() { return g_threshold.load(std::memory_order_relaxed); }
void set_parallel_threshold(int items) { g_threshold.store(items, std::memory_order_relaxed); }
}  // namespace mrsim
