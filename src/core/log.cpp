#include "core/log.hpp"

#include <atomic>
#include <iostream>

namespace mrsim {
namespace {
std::atomic<bool> g_quiet{false};
}
void set_quiet(bool quiet) { g_quiet = quiet; }
bool is_quiet() { return g_quiet; }
void warn(std::string_view message) {
  if (!g_quiet) std::cerr << "warning: " << message << '\n';
}
void info(std::string_view message) {
  if (!g_quiet) std::cerr << message << '\n';
}
}  // namespace mrsim
