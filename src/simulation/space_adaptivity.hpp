#pragma once
// The split/merge decisions of method.md §3.3, once per display frame: the quality indicator
// c_i = h_i ‖Δu_i‖ on every active point; splits above `refine_above`, worst first, up to
// `max_level` and an optional cap on active points; merges of subdivided points whose active
// children are all below `coarsen_below` (hysteresis: coarsen_below < refine_above / r) after
// at least `min_dwell_frames` frames, finest first; then garbage collection of ghosts (§4.7).
// [Eng] With `calm_frames` n > 1 the children must have been below `coarsen_below` at the last
// n frame ends in a row: a body that swings passes near its rest shape every half period, where
// Δu is small everywhere, and one calm sample there merged the swinging beam mid-swing
// (docs/hierarchy.md "Calm over a swing").
// [Eng] Under the tools the finest level is made active before contact (contact_lookahead):
// a skin vertex moved by a coarse level while a tool presses it jumps when a finer level takes
// over (the coarse level cannot represent the dent), and so would the tool force.
// [Eng] An active point most of whose same-level neighbours are subdivided splits with them,
// and a subdivided point in that situation does not merge: such an island may have no
// criterion of its own (a corner point with a single tet has Δu = 0 for any field) and, left
// coarse, carries its whole lumped mass inside a finer region (a spurious slow mode).
#include <cstdint>
#include <string>
#include <vector>

#include "physics/laplacian_criterion.hpp"
#include "simulation/hierarchical_simulation.hpp"

namespace mrsim {

struct SpaceAdaptivitySettings {
  bool enabled = false;
  double refine_above = 0.05;
  double coarsen_below = 0.0125;
  int max_level = 1 << 30;           // clamped to the last level
  std::int64_t max_active_points = 0;  // 0: no cap
  int min_dwell_frames = 5;
  int calm_frames = 1;  // successive calm frame ends before a merge (1: the thesis' rule)
  // Contact refines ahead of the tools (method.md §6.2 [Eng]): the active points that move a
  // skin vertex a tool may reach within this many seconds split whatever their criterion, and
  // their parents do not merge. 0: off (no tool).
  double contact_lookahead = 0;
  // Refine ahead of the applied loads (issue 16 point 2): c is also taken on the displacement
  // the loads alone would add within this many seconds, u + ½ T² (g + f_ext/m), so a sudden
  // load refines where it will bend the body before the frame that bends it, not one frame
  // after. 0: off (the thesis' rule).
  double predict_horizon = 0;
  // The loads in that prediction are the largest the profiles reach within this many seconds
  // (at least predict_horizon): a split adds one level per frame, so a load ramped in from zero
  // must be seen as many frames ahead as there are levels to go through.
  double predict_window = 0;
  Vec3 gravity = Vec3::Zero();  // m/s², with the loads and contacts: the applied accelerations
};

/// The real-time budget rule (method.md §6.2 point 5; thesis §5.2), decided from the wall
/// time of the last frame's simulation: Free, no split (over `fraction` of the frame), or no
/// split and the calmest subdivided points merged (over the whole frame).
enum class BudgetRule { Free, HoldSplits, Shed };

struct HierarchyEvent {
  int frame = 0;
  std::string kind;  // "split", "merge", "gc"
  int level = 0;
  long long point = -1;  // for gc: number of support ghosts released
};

class SpaceAdaptivity {
 public:
  SpaceAdaptivity(const SpaceAdaptivitySettings& settings, const HierarchicalSimulation& sim);
  /// Evaluates the criterion, splits/merges, collects garbage and applies the changes.
  /// Appends what happened to `events`.
  void update(HierarchicalSimulation& sim, int frame, std::vector<HierarchyEvent>& events,
              BudgetRule budget = BudgetRule::Free);
  /// Within a frame (adaptivity.space.split_checks): the criterion and the splits only; merges
  /// and their dwell wait for the frame's end. Appends the splits to `events`.
  void split_within_frame(HierarchicalSimulation& sim, int frame,
                          std::vector<HierarchyEvent>& events);
  /// c_i of the last update, per level (0 where the point is not active).
  const std::vector<double>& criterion(int level) const { return criterion_[level]; }
  /// Frame of the last split of every point (-1: never), per level, and how many frame ends in
  /// a row each subdivided point's children have been calm: what a checkpoint keeps (the
  /// criterion and the contact region are recomputed at every update).
  const std::vector<std::vector<int>>& split_frames() const { return split_frame_; }
  const std::vector<std::vector<int>>& calm_streaks() const { return calm_streak_; }
  /// Takes them back; throws std::invalid_argument when the sizes do not match the levels.
  void restore(std::vector<std::vector<int>> split_frames,
               std::vector<std::vector<int>> calm_streaks);
  /// Evaluates the criterion only (for output when adaptivity is off).
  void evaluate(const HierarchicalSimulation& sim);

 private:
  void split_worst(HierarchicalSimulation& sim, int frame, std::vector<HierarchyEvent>& events);
  void split_islands(HierarchicalSimulation& sim, int frame, std::int64_t& active,
                     std::vector<HierarchyEvent>& events);
  bool split_within_cap(HierarchicalSimulation& sim, int l, int p, int frame, std::int64_t& active,
                        std::vector<HierarchyEvent>& events);
  void merge_calm(HierarchicalSimulation& sim, int frame, std::vector<HierarchyEvent>& events);
  void apply(HierarchicalSimulation& sim, int frame, std::vector<HierarchyEvent>& events);
  void shed(HierarchicalSimulation& sim, int frame, std::vector<HierarchyEvent>& events);

  SpaceAdaptivitySettings s_;
  std::vector<std::vector<double>> criterion_;
  TetGradientCache gradients_;  // evaluate()'s scratch, one level at a time
  // predict_horizon > 0: the predicted displacement of every point (ghosts interpolated from
  // their sources' predictions) and scratch for the velocities update_ghosts also fills.
  std::vector<std::vector<Vec3>> predicted_, scratch_;
  void add_predicted(const HierarchicalSimulation& sim);
  std::vector<std::vector<int>> split_frame_;  // frame of the last split of each point
  std::vector<std::vector<int>> calm_streak_;  // frame ends in a row its children were calm
  void count_calm(const HierarchicalSimulation& sim);
  std::vector<std::vector<std::uint8_t>> contact_;  // 1: moves a skin vertex a tool may reach
  std::vector<std::pair<int, int>> region_;          // (level, point) with contact_ set
  void mark_contact_region(const HierarchicalSimulation& sim);
  bool holds_contact(const HierarchicalSimulation& sim, int l, int p) const;
  double worst_child(const HierarchicalSimulation& sim, int l, int p) const;
};

}  // namespace mrsim
