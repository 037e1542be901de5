#pragma once
// Per-particle time levels on the multiresolution model (method.md §5.2, §5.4): every free
// active point is kicked with its own step frame_dt / 2^k at the ticks the W-cycle gives its
// level (time/w_cycle.hpp), and each sub-step evaluates forces only where they are needed: on
// the particles it kicks, on the ghosts whose force reaches them (energy coupling) and on the
// tets of those. Ghosts have no time level; the simulation drifts every particle and refreshes
// the ghosts before each sub-step, so forces always see the current time.
//
// A particle refined at once (velocity-change rule) has already been kicked for the rest of its
// coarse step; it waits in `pending_` until its first kick on the finer level.
#include <cstdint>
#include <vector>

#include "hierarchy/ghost_force_transfer.hpp"
#include "hierarchy/status_lists.hpp"
#include "simulation/level_force_field.hpp"
#include "time/point_state.hpp"
#include "time/time_level_rules.hpp"
#include "time/w_cycle.hpp"

namespace mrsim {

struct TimeLevelChange {
  int level = 0, point = 0;  // space level and point
  int from = 0, to = 0;      // time levels
};

class TimeAdaptivity {
 public:
  TimeAdaptivity(const Hierarchy& h, const StatusLists& lists,
                 const std::vector<const LevelModel*>& models,
                 const std::vector<LevelForceField*>& fields,
                 const std::vector<PointState>& states,
                 const std::vector<std::vector<double>>& stable_dt, const TimeLevelRules& rules);

  const TimeLevelRules& rules() const { return rules_; }
  const WCycle& schedule() const { return wc_; }

  /// After the active sets changed (and at the start): every active particle's stable level is
  /// read again from `stable_dt` (s, per space level and point, kept up to date by the
  /// simulation); points that became active start there, points on a coarser level move to it,
  /// points that left lose theirs. Only at a frame boundary.
  void refile();
  /// At a frame start, after the stable steps changed without a topology change (the contact
  /// near the tools): particles whose level became too coarse move finer; the lists are
  /// rebuilt only then. O(active).
  void restable();

  /// One sub-step of the frame: its tick and the time levels it kicks (-1: none).
  struct SubStep {
    int tick = 0;
    int levels[2] = {-1, -1};
  };
  void begin_frame();
  bool frame_done() const { return tick_ >= wc_.ticks_per_frame(); }
  /// Prepares the next tick: brings in pending particles due there, rebuilds stale force
  /// subsets, and points every level's force field at this tick's subset.
  SubStep next();
  /// Particles of time level k on space level l kicked at its ticks (sorted).
  const std::vector<int>& kicked(int k, int l) const { return lists_[k][l]; }
  /// The ghosts whose force the current sub-step needs, for the restricted force transfer.
  const GhostSelection& ghosts() const { return selection_; }
  /// After the sub-step's kicks: the velocity-change rule on the particles just kicked
  /// (refinement at once); `changes` gets the refinements.
  void after_step(const SubStep& s, std::vector<TimeLevelChange>& changes);
  /// At the end of the frame: coarsening with hysteresis; `changes` gets them.
  void end_frame(std::vector<TimeLevelChange>& changes);
  /// Back to evaluating every served point (outputs, probes).
  void release_fields();

  /// Checkpoints (at a frame boundary: nothing pending, δ max reset): every particle's time
  /// level and stable level per space level, and the evaluation counters.
  const std::vector<std::vector<std::int8_t>>& time_levels() const { return time_level_; }
  const std::vector<std::vector<std::int8_t>>& stable_levels() const { return stable_level_; }
  /// Takes them back after refile(); throws std::invalid_argument on a size or level out of
  /// range.
  void restore(std::vector<std::vector<std::int8_t>> time_level,
               std::vector<std::vector<std::int8_t>> stable_level,
               std::vector<std::int64_t> evaluations);

  /// Time level of point p of space level l, -1 when it is not integrated.
  int level_of(int l, int p) const { return time_level_[l][p]; }
  /// Integrated particles per time level (all space levels), [max_level + 1].
  std::vector<std::int64_t> particles_per_level() const;
  /// Cumulative point-force evaluations per time level, [max_level + 1].
  const std::vector<std::int64_t>& evaluations() const { return evaluations_; }
  /// Particles kicked by each sub-step of the current (or last) frame that kicked any: the
  /// schedule's work per sub-step, whose max / mean the W-cycle keeps small.
  const std::vector<std::int64_t>& frame_work() const { return frame_work_; }

 private:
  int num_levels() const { return static_cast<int>(models_.size()); }
  void rebuild_lists();
  void rebuild_subsets(int k);
  void mark_needed_ghosts(int k);
  void bring_in_pending(int tick);
  bool populated(int k) const;
  bool follow_stable_steps();
  void use_subsets(int kc);

  const Hierarchy& h_;
  const StatusLists& status_;
  std::vector<const LevelModel*> models_;
  std::vector<LevelForceField*> fields_;
  const std::vector<PointState>& states_;
  const std::vector<std::vector<double>>& stable_dt_;
  TimeLevelRules rules_;
  WCycle wc_;
  int K_ = 0;     // the finest time level (rules.max_level)
  int tick_ = 0;  // the next tick of the frame
  std::vector<std::vector<std::int8_t>> time_level_, stable_level_;  // [space level][point]
  std::vector<std::vector<float>> delta_max_;                    // δ max over the frame
  std::vector<std::vector<std::vector<int>>> lists_;             // [k][l]
  struct Pending {
    int level, point, k, due;  // due: the tick of its first kick on level k
  };
  std::vector<Pending> pending_;
  // Force subsets and needed ghosts per time level, rebuilt when stale.
  std::vector<std::vector<FieldSubset>> subset_;              // [k][l]
  std::vector<std::vector<std::vector<int>>> need_iface_, need_sub_;  // [k][l]
  std::vector<std::uint8_t> stale_;                            // [k]
  std::vector<std::vector<std::uint8_t>> reach_;               // [l][point], scratch marks
  std::vector<int> ghosts_scratch_;
  // The current sub-step's merged subsets and ghosts (two levels).
  std::vector<FieldSubset> merged_;                            // [l]
  std::vector<std::vector<int>> merged_iface_, merged_sub_;    // [l]
  GhostSelection selection_;
  std::vector<std::int64_t> evaluations_;
  std::vector<std::int64_t> frame_work_;
};

}  // namespace mrsim
