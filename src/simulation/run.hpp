#pragma once
// A whole run (product.md "What a run writes"): load and check the input, simulate frame by
// frame, write scenario.yaml, frames.pvd + frames/, log.h5 and summary.json into the output
// folder. Input problems throw InputError before anything is written; a divergence or an I/O
// failure during the run throws RunError after every output of the frames before it is closed
// and valid (summary.json records the failure).
#include <cstdint>
#include <filesystem>
#include <functional>

#include "scenario/scenario.hpp"

namespace mrsim {

struct RunProgress {
  int frame = 0, frames = 0;     // frames done / total
  double simulated_time = 0;     // s
  double wall_elapsed = 0;       // s
};

struct RunOptions {
  std::function<void(const RunProgress&)> progress;  // called after every frame
};

struct RunSummary {
  int frames = 0;
  std::int64_t steps = 0;
  double simulated_time = 0;  // s, frames × time.frame_dt
  double wall_time = 0;
  int interrupted_by = 0;  // SIGINT / SIGTERM that stopped the run after a whole frame, or 0
};

/// Simulated seconds per wall second of the whole run (set-up included); 0 before any time.
inline double real_time_factor(const RunSummary& s) {
  return s.wall_time > 0 ? s.simulated_time / s.wall_time : 0.0;
}

RunSummary run_scenario(const Scenario& scenario, const RunOptions& options = {});

/// Goes on with the run in `dir` from its checkpoint.h5 (mrsim run --resume; docs/output.md
/// "Checkpoints and --resume"): the folder's scenario.yaml, the checkpoint's copy of log.h5,
/// the frames cut back to the checkpoint's frame, then the remaining frames, written as the
/// uninterrupted run would have written them. Throws InputError (before anything is changed) when there is no
/// checkpoint, when it belongs to another scenario or build, or when the run completed.
RunSummary resume_run(const std::filesystem::path& dir, const RunOptions& options = {});

/// Loads every mesh of the scenario and checks it against the scenario (fixed regions, loads,
/// time step): what `mrsim check` does beyond the schema. Returns the scenario with
/// time.substeps computed when it was omitted. Throws InputError.
Scenario check_scenario_inputs(const Scenario& scenario);

}  // namespace mrsim
