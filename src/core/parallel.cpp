#include "core/parallel.hpp"

#include <atomic>

namespace mrsim {
namespace {
std::atomic<int> g_threshold{8192};
}
int parallel_threshold() { return g_threshold.load(std::memory_order_relaxed); }
void set_parallel_threshold(int items) { g_threshold.store(items, std::memory_order_relaxed); }
}  // namespace mrsim
