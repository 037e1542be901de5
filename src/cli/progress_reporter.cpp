#include "cli/progress_reporter.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace mrsim {

namespace {

std::string format_duration(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm%02lds", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  return buf;
}

}  // namespace

ProgressReporter::ProgressReporter(bool enabled)
    : enabled_(enabled), terminal_(isatty(STDERR_FILENO) == 1) {}

void ProgressReporter::operator()(const RunProgress& p) {
  if (!enabled_ || p.frames <= 0) return;
  const double fraction = static_cast<double>(p.frame) / p.frames;
  const int percent = static_cast<int>(100 * fraction);
  const double eta = p.frame > 0 ? p.wall_elapsed * (p.frames - p.frame) / p.frame : 0;
  // Simulated seconds per wall second so far (set-up included), as summary.json's
  // real_time_factor.
  const double pace = p.wall_elapsed > 0 ? p.simulated_time / p.wall_elapsed : 0;
  if (terminal_) {
    const int width = 30, filled = static_cast<int>(width * fraction);
    std::fprintf(stderr, "\r[%s%s] %3d%% frame %d/%d t=%.4gs %.3gx real time elapsed %s ETA %s ",
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(),
                 percent, p.frame, p.frames, p.simulated_time, pace,
                 format_duration(p.wall_elapsed).c_str(), format_duration(eta).c_str());
    drawn_ = true;
  } else if (percent / 5 != last_percent_ / 5 || p.frame == p.frames) {
    std::fprintf(stderr,
                 "progress: frame %d/%d (%d%%) t=%.6gs %.3gx real time elapsed %s ETA %s\n",
                 p.frame, p.frames, percent, p.simulated_time, pace,
                 format_duration(p.wall_elapsed).c_str(), format_duration(eta).c_str());
  }
  last_percent_ = percent;
  std::fflush(stderr);
}

void ProgressReporter::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace mrsim
