#pragma once
// What a checkpoint holds (docs/output.md "Checkpoints and --resume"): the state a run needs to
// go on from the end of a display frame exactly as if it had never stopped. Plain data, written
// and read by io/checkpoint_file.hpp, taken from and given back to the simulation by
// simulation/checkpoint_state.hpp. Everything that is a function of the topology (status lists,
// interface masses and weights, stable steps, load targets, skin map) is not stored: it is
// rebuilt from the hierarchy's counters by the code that builds it during a run.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/task_clock.hpp"
#include "core/vec.hpp"

namespace mrsim {

/// One level's dynamic state and hierarchy counters, one entry per point.
struct LevelCheckpoint {
  std::vector<Vec3> u, v, f;         // displacement, velocity, last force
  std::vector<Vec3> f_kick;          // Störmer–Verlet's saved half-kick force (else empty)
  std::vector<Vec3> u_prev, v_prev;  // Newton–Cotes' previous step (else empty)
  std::vector<std::uint8_t> subdivided, support;  // hierarchy flags (method.md §4.2)
  std::vector<std::int32_t> active_ref, ghost_ref;
  std::vector<std::int32_t> split_frame;              // space adaptivity: frame of the last split
  std::vector<std::int32_t> calm_streak;              // and calm frame ends in a row (merges)
  std::vector<std::int8_t> time_level, stable_level;  // per-particle time levels (else empty)
};

/// The simulation's own scalars and counters.
struct SimulationCheckpoint {
  double time = 0;         // s, simulated time at the frame's end
  double clock = 0;        // s, the time positions were last moved to
  double external_at = 0;  // s, the time external forces were last evaluated at
  double dt = 0;           // s, the global step (without time levels)
  std::int64_t frames = 0, steps = 0;
  std::int32_t steps_per_frame = 1;
  double previous_dt = 0;                            // Newton–Cotes: step of u_prev, v_prev
  std::vector<std::int64_t> block_evaluations;       // per integration block
  std::vector<std::int64_t> tet_updates;             // per level
  std::vector<std::int64_t> time_level_evaluations;  // per time level (else empty)
  std::vector<std::vector<std::int32_t>> contact_candidates;  // per tool, skin vertices
  std::vector<LevelCheckpoint> levels;
};

/// The run's counters at the checkpoint's frame, and how much of each log.h5 table belongs to
/// the frames up to it (a run killed later may have written more).
struct RunCheckpoint {
  std::int32_t frame = 0;  // the last frame written; the run goes on with frame + 1
  std::int32_t frames_total = 0;
  double max_displacement = 0;
  std::int64_t splits = 0, merges = 0, budget_hold = 0, budget_shed = 0;
  std::int32_t substep_changes = 0;
  double peak_tool_force = 0;
  double wall_time = 0;  // s, the run's wall time so far
  TaskClock::Parts wall_time_parts{};
  std::int64_t log_events = 0;                 // rows of /events
  std::vector<std::int64_t> log_tool_samples;  // rows of /tool, /tool_k
};

struct Checkpoint {
  static constexpr std::int64_t kFormatVersion = 3;  // 2: /log_h5; 3: calm_streak
  std::string mrsim_version, git_revision;
  std::string scenario_yaml;    // the resolved scenario the run was started with
  std::string scenario_source;  // absolute path of its file: relative mesh paths start there
  RunCheckpoint run;
  SimulationCheckpoint simulation;
};

}  // namespace mrsim
