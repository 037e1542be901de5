#pragma once
// Wall time per task of a run, as the thesis reports it (§5: model 60 %, surface 5 %,
// collision 20 %, display 15 %): log.h5 /frames/wall_time_parts, summary.json "time_shares"
// (docs/output.md). A few clock reads per step (the force pass of all levels is one), never per
// point.
#include <array>
#include <chrono>
#include <cstddef>

namespace mrsim {

enum class Task : int {
  InternalForces,  // strain and damping forces of every level (physics/internal_force)
  Ghosts,          // ghost displacement updates and ghost force transfers (§4.8)
  Contact,         // skin, broad phase, contact forces and surface loads
  Integration,     // kicks, drifts, semi-implicit filter, time-level bookkeeping
  Adaptivity,      // criterion, splits and merges, rebuilds at topology changes
  Output,          // VTK frames and the log row's gathering
  Other,           // the rest of the frame (energies, divergence check, progress)
};
inline constexpr std::size_t kTaskCount = 7;
inline constexpr std::array<const char*, kTaskCount> kTaskNames = {
    "internal_forces", "ghosts", "contact", "integration", "adaptivity", "output", "other"};

class TaskClock {
 public:
  using Clock = std::chrono::steady_clock;
  using Parts = std::array<double, kTaskCount>;

  /// Adds the time since `start` to `task` and returns now (to chain measurements).
  Clock::time_point add_since(Task task, Clock::time_point start) {
    const Clock::time_point now = Clock::now();
    parts_[static_cast<int>(task)] += std::chrono::duration<double>(now - start).count();
    return now;
  }
  void add(Task task, double seconds) { parts_[static_cast<int>(task)] += seconds; }
  double part(Task task) const { return parts_[static_cast<int>(task)]; }
  const Parts& parts() const { return parts_; }
  void reset() { parts_.fill(0.0); }

 private:
  Parts parts_{};
};

/// Times a scope into one task of a clock (nullptr: no timing).
class TaskTimer {
 public:
  TaskTimer(TaskClock* clock, Task task)
      : clock_(clock),
        task_(task),
        start_(clock ? TaskClock::Clock::now() : TaskClock::Clock::time_point{}) {}
  ~TaskTimer() {
    if (clock_) clock_->add_since(task_, start_);
  }
  TaskTimer(const TaskTimer&) = delete;
  TaskTimer& operator=(const TaskTimer&) = delete;

 private:
  TaskClock* clock_;
  Task task_;
  TaskClock::Clock::time_point start_;
};

}  // namespace mrsim
