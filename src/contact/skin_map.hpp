#pragma once
// Which active points move each skin vertex, and with which weights (method.md §6.2 point 1):
// the vertex follows the finest level whose bound tet has no inactive vertex (level 0 always
// qualifies); through the ghosts' interpolation rows it is a fixed linear combination of active
// points until the next topology change. The same weights carry a contact force back to those
// points (the transpose), so the force's virtual work equals the work on the skin.
//
// Only the vertices near a tool need that row (the contact force, the refinement ahead of the
// tool); the others need a position once a frame (the broad phase, the output), which their
// level's tet gives directly, its vertices being active points or ghosts refreshed at every
// step. So a build picks each vertex's level and tet (O(skin vertices)), and a row is merged
// the first time it is asked for until the next build.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "contact/skin_binding.hpp"
#include "hierarchy/active_row.hpp"
#include "hierarchy/ghost_update.hpp"
#include "hierarchy/merged_rows.hpp"

namespace mrsim {

class SkinMap {
 public:
  /// After every topology change. `h` and `free_point` are read again by row() until the next
  /// build, so they must outlive it unchanged.
  void build(const Hierarchy& h, const SkinBinding& binding,
             const std::vector<const std::vector<std::uint8_t>*>& free_point);

  int size() const { return static_cast<int>(level_.size()); }
  /// Level whose tet moves skin vertex s.
  int level(int s) const { return level_[s]; }
  /// Displacement and velocity of skin vertex s from its level's tet in `fields` (whose ghosts
  /// are current): the value of its row up to rounding, in O(1).
  void interpolate(int s, const std::vector<LevelFields>& fields, Vec3& u, Vec3& v) const;
  /// The active points that move skin vertex s (level -1: held by the support), sorted by
  /// (level, point). Merged at the first call after a build (hierarchy/merged_rows.hpp); the
  /// span stays valid until the next row is merged or the next build.
  std::span<const ActiveTerm> row(int s) const;
  /// Displacement (or velocity, with the v fields) of skin vertex s through its row.
  Vec3 value(int s, const std::vector<LevelFields>& fields, bool velocity) const;

 private:
  std::vector<int> level_;
  std::vector<std::array<int, 4>> source_;  // the tet's vertices at level_[s]
  std::vector<Bary> weight_;                // and their coordinates
  std::vector<int> undecided_;              // build()'s vertices without a level yet
  const Hierarchy* h_ = nullptr;
  std::vector<const std::vector<std::uint8_t>*> free_;

  // Rows merged on demand since the last build (logically const: a cache of the map).
  mutable std::vector<int> begin_, end_;  // [begin, end) in terms_, or begin_ = -1
  mutable std::vector<int> built_;        // the vertices with a row, to reset at the next build
  mutable std::vector<ActiveTerm> terms_;
  mutable std::vector<ActiveTerm> scratch_;
  mutable MergedRows rows_;  // the points' rows, shared within a build
};

}  // namespace mrsim
