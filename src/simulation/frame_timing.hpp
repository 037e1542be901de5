#pragma once
// The wall time of one display frame per task (core/task_clock.hpp, log.h5
// /frames/wall_time_parts). The simulation times its own tasks (internal forces, ghosts,
// contact); the run loop times the phases around them (integration, adaptivity, output). A
// phase is charged its elapsed time less what the simulation's timers counted meanwhile, so
// nothing is counted twice, and what no timer saw is `other`: the parts sum to the frame, plus
// what was carried into it (carry()).
#include <algorithm>
#include <chrono>
#include <numeric>

#include "core/task_clock.hpp"

namespace mrsim {

class FrameTiming {
 public:
  using Clock = TaskClock::Clock;

  explicit FrameTiming(TaskClock& clock) : clock_(clock) { restart(); }

  /// The frame starts now.
  void restart() {
    start_ = Clock::now();
    at_start_ = clock_.parts();
    carried_ = {};
  }

  /// Charges `task` with `seconds` spent for this frame before its clock started: the previous
  /// frame's log row, whose writing that row cannot hold. finish() adds it beside the rest.
  void carry(Task task, double seconds) { carried_[static_cast<std::size_t>(task)] += seconds; }

  Clock::time_point start() const { return start_; }

  /// Everything the clock has counted so far (s): pass it to add_phase.
  double counted() const {
    const TaskClock::Parts& p = clock_.parts();
    return std::accumulate(p.begin(), p.end(), 0.0);
  }

  /// Charges `task` with the time since `phase_start`, less what was counted since
  /// `counted_before` (= counted() at phase_start).
  void add_phase(Task task, Clock::time_point phase_start, double counted_before) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - phase_start).count();
    clock_.add(task, std::max(0.0, elapsed - (counted() - counted_before)));
  }

  template <class Phase>
  void phase(Task task, Phase&& run) {
    const Clock::time_point t = Clock::now();
    const double before = counted();
    run();
    add_phase(task, t, before);
  }

  /// The frame's parts since restart(); `other` is the rest of its wall time so far.
  TaskClock::Parts finish() const {
    TaskClock::Parts parts = clock_.parts();
    for (std::size_t k = 0; k < kTaskCount; ++k) parts[k] -= at_start_[k];
    const auto other = static_cast<std::size_t>(Task::Other);
    parts[other] = 0;
    const double seen = std::accumulate(parts.begin(), parts.end(), 0.0);
    const double total = std::chrono::duration<double>(Clock::now() - start_).count();
    parts[other] = std::max(0.0, total - seen);
    for (std::size_t k = 0; k < kTaskCount; ++k) parts[k] += carried_[k];
    return parts;
  }

 private:
  TaskClock& clock_;
  Clock::time_point start_;
  TaskClock::Parts at_start_{};
  TaskClock::Parts carried_{};
};

}  // namespace mrsim
