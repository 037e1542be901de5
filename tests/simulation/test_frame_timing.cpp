// The wall time per task of a frame (simulation/frame_timing.hpp, log.h5
// /frames/wall_time_parts): a phase is charged its elapsed time less what the simulation's own
// timers counted inside it, so nothing is counted twice and the parts sum to the frame.
#include <gtest/gtest.h>

#include <numeric>
#include <thread>

#include "simulation/frame_timing.hpp"

namespace mrsim {
namespace {

using namespace std::chrono_literals;

double sum(const TaskClock::Parts& p) { return std::accumulate(p.begin(), p.end(), 0.0); }
double part(const TaskClock::Parts& p, Task t) { return p[static_cast<int>(t)]; }

TEST(FrameTiming, PhasesDoNotCountTheInnerTimersTwice) {
  TaskClock clock;
  clock.add(Task::Output, 5.0);  // an earlier frame: not part of this one
  // Read before the frame's own clock starts: the frame lies within [t0, now()].
  const auto t0 = TaskClock::Clock::now();
  FrameTiming timing(clock);
  timing.phase(Task::Integration, [&] {
    std::this_thread::sleep_for(30ms);
    clock.add(Task::InternalForces, 0.010);  // what a force field's TaskTimer counted inside
  });
  std::this_thread::sleep_for(5ms);  // seen by no timer: `other`
  const TaskClock::Parts parts = timing.finish();
  const double total = std::chrono::duration<double>(TaskClock::Clock::now() - t0).count();

  EXPECT_DOUBLE_EQ(part(parts, Task::InternalForces), 0.010);
  EXPECT_DOUBLE_EQ(part(parts, Task::Output), 0.0);
  EXPECT_GE(part(parts, Task::Integration), 0.030 - 0.010 - 1e-4);
  EXPECT_GE(part(parts, Task::Other), 0.005 - 1e-4);
  // Counted twice, the integration phase would make the parts exceed the frame's wall time.
  EXPECT_LE(sum(parts), total + 1e-9);
  EXPECT_NEAR(sum(parts), total, 1e-3);
}

// The previous frame's log row is written after that row took its parts: its time is carried
// into the next frame's output, beside the frame's own clock, and restart() forgets it.
TEST(FrameTiming, CarriedTimeIsAddedToItsTaskAndNotTakenFromOther) {
  TaskClock clock;
  const auto t0 = TaskClock::Clock::now();
  FrameTiming timing(clock);
  timing.carry(Task::Output, 0.25);
  std::this_thread::sleep_for(5ms);
  const TaskClock::Parts parts = timing.finish();
  const double total = std::chrono::duration<double>(TaskClock::Clock::now() - t0).count();
  EXPECT_DOUBLE_EQ(part(parts, Task::Output), 0.25);
  EXPECT_GE(part(parts, Task::Other), 0.005 - 1e-4);
  EXPECT_NEAR(sum(parts), total + 0.25, 1e-3);
  timing.restart();
  EXPECT_EQ(part(timing.finish(), Task::Output), 0.0);
}

TEST(FrameTiming, TaskTimerAddsItsScopeAndNullIsNotTimed) {
  TaskClock clock;
  {
    const TaskTimer timer(&clock, Task::Ghosts);
    std::this_thread::sleep_for(2ms);
  }
  { const TaskTimer untimed(nullptr, Task::Ghosts); }
  EXPECT_GE(clock.part(Task::Ghosts), 0.002 - 1e-4);
  EXPECT_EQ(sum(clock.parts()), clock.part(Task::Ghosts));
  EXPECT_EQ(kTaskNames.size(), kTaskCount);
  EXPECT_STREQ(kTaskNames[static_cast<int>(Task::Other)], "other");
}

}  // namespace
}  // namespace mrsim
