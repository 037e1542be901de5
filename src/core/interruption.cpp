#include "core/interruption.hpp"

#include <csignal>

namespace mrsim {

namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_interruption(int sig) {
  if (g_signal != 0) {  // the second one: stop now, the default way
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
}

}  // namespace

void watch_interruptions() {
  struct sigaction action {};
  action.sa_handler = on_interruption;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls under way (file writes) go on
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interruption_signal() { return static_cast<int>(g_signal); }

}  // namespace mrsim
