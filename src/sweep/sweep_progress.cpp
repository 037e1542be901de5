#include "sweep/sweep_progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace mrsim::sweep {

SweepProgress::SweepProgress(int total, int already_done, int already_failed, int jobs,
                             bool enabled)
    : total_(total),
      done_(already_done),
      failed_(already_failed),
      jobs_(std::max(1, jobs)),
      enabled_(enabled),
      terminal_(isatty(STDERR_FILENO) != 0) {}

void SweepProgress::started() {
  ++running_;
  if (terminal_) print();
}

void SweepProgress::finished(bool ok) {
  --running_;
  ++done_;
  ++finished_here_;
  if (!ok) ++failed_;
  print();
}

void SweepProgress::close() {
  if (enabled_ && terminal_) std::cerr << '\n';
}

std::string SweepProgress::line() const {
  std::string text = "sweep: " + std::to_string(done_) + "/" + std::to_string(total_) +
                     " done, " + std::to_string(failed_) + " failed, " +
                     std::to_string(running_) + " running";
  if (finished_here_ > 0 && done_ < total_) {
    // Wall time per finished case already reflects the `jobs_` cases running side by side.
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double per_case = elapsed / finished_here_;
    text += ", ETA " + format_duration(per_case * (total_ - done_));
  }
  return text;
}

void SweepProgress::print() {
  if (!enabled_) return;
  if (terminal_)
    std::cerr << '\r' << line() << "\x1b[K" << std::flush;
  else
    std::cerr << line() << '\n';
}

std::string format_duration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buffer[32];
  if (s < 60)
    std::snprintf(buffer, sizeof buffer, "%lds", s);
  else if (s < 3600)
    std::snprintf(buffer, sizeof buffer, "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(buffer, sizeof buffer, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  return buffer;
}

}  // namespace mrsim::sweep
