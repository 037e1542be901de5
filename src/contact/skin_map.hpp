#pragma once
// Which active points move each skin vertex, and with which weights (method.md §6.2 point 1):
// the vertex follows the finest level whose bound tet has no inactive vertex (level 0 always
// qualifies); through the ghosts' interpolation rows it is a fixed linear combination of active
// points until the next topology change. The same weights carry a contact force back to those
// points (the transpose), so the force's virtual work equals the work on the skin.
#include <cstdint>
#include <vector>

#include "contact/skin_binding.hpp"
#include "hierarchy/active_row.hpp"
#include "hierarchy/ghost_update.hpp"
#include "hierarchy/merged_rows.hpp"

namespace mrsim {

class SkinMap {
 public:
  /// Rebuilt after every topology change; O(skin vertices × row length). Each point's row is built
  /// once per build and shared (hierarchy/merged_rows.hpp).
  void build(const Hierarchy& h, const SkinBinding& binding,
             const std::vector<const std::vector<std::uint8_t>*>& free_point);

  int size() const { return static_cast<int>(level_.size()); }
  /// Level whose tet moves skin vertex s.
  int level(int s) const { return level_[s]; }
  /// Displacement (or velocity, with the v fields) of skin vertex s.
  Vec3 value(int s, const std::vector<LevelFields>& fields, bool velocity) const;
  /// Both at once, in one pass over the row (the same sums as value()).
  void values(int s, const std::vector<LevelFields>& fields, Vec3& u, Vec3& v) const;
  const ActiveTerm* begin(int s) const { return terms_.data() + start_[s]; }
  const ActiveTerm* end(int s) const { return terms_.data() + start_[s + 1]; }

 private:
  std::vector<int> level_;
  std::vector<int> start_{0};
  std::vector<ActiveTerm> terms_;  // merged per (level, point), sorted
  std::vector<ActiveTerm> row_;    // scratch

  MergedRows rows_;  // the points' rows, shared within a build
};

}  // namespace mrsim
