#pragma once
// Dynamic statuses of the points of every level (method.md §4.2, §4.4–4.7): which points are
// simulated (active), which copy their displacement from another level (ghosts), which are
// ignored (inactive). Statuses are derived from per-point counters, never stored, so split and
// merge are exact inverses. Purely combinatorial: the dynamics read it (simulation/).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "hierarchy/level_links.hpp"

namespace mrsim {

enum class NodeState : std::int8_t {
  Inactive,    // not simulated, not needed
  Active,      // computes its force and integrates
  GhostSub,    // subdivided: interpolates from its child tet (finer level)
  GhostIface,  // interface ghost: interpolates from its parent tet (coarser level)
};

/// The per-point counters of one level that every status derives from (method.md §4.2).
struct HierarchyCounters {
  std::vector<std::uint8_t> subdivided, support;
  std::vector<int> active_ref, ghost_ref;
};

class Hierarchy {
 public:
  /// Initial state: every level-0 point active, nothing else.
  Hierarchy(std::vector<HierarchyLevel> levels, std::vector<LevelLinks> links);

  int num_levels() const { return static_cast<int>(levels_.size()); }
  int num_points(int level) const { return static_cast<int>(flags_[level].subdivided.size()); }
  /// The status that follows from the counters (inline: the skin map and the lists ask for it per
  /// point at every topology change).
  NodeState state(int level, int point) const {
    const Flags& f = flags_[level];
    if (f.subdivided[point]) return NodeState::GhostSub;
    if (level == 0 || f.active_ref[point] > 0) return NodeState::Active;
    if (f.ghost_ref[point] > 0 || f.support[point]) return NodeState::GhostIface;
    return NodeState::Inactive;
  }
  bool subdivided(int level, int point) const { return flags_[level].subdivided[point] != 0; }
  const LevelLinks& links(int level) const { return links_[level]; }
  const HierarchyLevel& level(int l) const { return levels_[l]; }

  /// Split preconditions of §4.4 (active, not finest, has children).
  bool can_split(int level, int point) const;
  /// Merge preconditions of §4.5 (subdivided, no member of its active set subdivided).
  bool can_merge(int level, int point) const;
  /// Returns the finer points that were inactive and are now simulated or ghosts (they need
  /// their displacement initialised by interpolation).
  std::vector<std::pair<int, int>> split(int level, int point);
  void merge(int level, int point);
  /// §4.7: recompute which inactive points are needed as interpolation sources; returns how
  /// many support points were released.
  int collect_garbage();

  /// I1–I5 of §4.9; empty when every invariant holds.
  std::vector<std::string> check_invariants() const;

  std::int64_t count(int level, NodeState s) const;

  /// Level l's counters, for a checkpoint.
  const HierarchyCounters& counters(int level) const { return flags_[level]; }
  /// Replaces every level's counters with a checkpoint's: every point counts as touched. Throws
  /// std::invalid_argument when the sizes do not match the levels, std::runtime_error when the
  /// result breaks an invariant of §4.9 (a checkpoint of another hierarchy).
  void restore(std::vector<HierarchyCounters> counters);

  /// Points whose status may have changed since the last call (duplicates possible), so the
  /// working lists are updated in O(changes) rather than O(all points).
  std::vector<std::pair<int, int>> take_touched() { return std::exchange(touched_, {}); }
  /// Has a status possibly changed since the last take_touched()?
  bool has_touched() const { return !touched_.empty(); }
  /// Counts every possible status change since construction: equal counts, equal statuses
  /// (what the frames' level ownership checks before looking at every tet again).
  std::uint64_t status_changes() const { return status_changes_; }

 private:
  using Flags = HierarchyCounters;
  void touch(int level, int point) {
    touched_.emplace_back(level, point);
    ++status_changes_;
  }
  void ensure_resolvable(int level, int ghost, std::vector<std::pair<int, int>>* woken);
  void check_point(int l, int p, std::vector<std::string>& out) const;

  std::vector<HierarchyLevel> levels_;
  std::vector<LevelLinks> links_;
  std::vector<Flags> flags_;
  std::vector<std::pair<int, int>> touched_;
  std::uint64_t status_changes_ = 0;
};

const char* node_state_name(NodeState s);

}  // namespace mrsim
