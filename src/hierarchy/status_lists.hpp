#pragma once
// Working lists of the points of each level by status (method.md §4.2: "per time level a list
// of active points"; §4.8: ghosts per level in update order). The simulation loops over these,
// so a step costs O(active + ghosts), never O(all points). Updated from Hierarchy::take_touched.
#include <array>
#include <vector>

#include "hierarchy/hierarchy.hpp"

namespace mrsim {

/// How a ghost is interpolated (method.md §4.8): the four points of its tet on the neighbouring
/// level (finer for a subdivided ghost, coarser for an interface ghost) and their weights,
/// copied out of the level links so that the ghost refresh and the force transfer of every
/// step read one record per ghost, in list order.
struct GhostStencil {
  std::array<int, 4> source;
  Bary weight;
};

class StatusLists {
 public:
  explicit StatusLists(const Hierarchy& h);
  /// Re-files the touched points under their current status: O(touched) plus a sort of each
  /// list that changed (once per display frame, not per step).
  void update(const Hierarchy& h, const std::vector<std::pair<int, int>>& touched);

  const std::vector<int>& active(int level) const { return lists_[level][kActive]; }
  const std::vector<int>& ghost_sub(int level) const { return lists_[level][kGhostSub]; }
  const std::vector<int>& ghost_iface(int level) const { return lists_[level][kGhostIface]; }
  /// The stencils of ghost_sub(level) and ghost_iface(level), entry k for the list's k-th
  /// ghost; rebuilt with the lists.
  const std::vector<GhostStencil>& sub_stencils(int level) const { return stencils_[level][0]; }
  const std::vector<GhostStencil>& iface_stencils(int level) const {
    return stencils_[level][1];
  }
  /// Lists are kept sorted by point index after update(): iteration order is deterministic
  /// and memory access follows the mesh numbering.
  std::size_t total(int which) const;

  static constexpr int kActive = 0, kGhostSub = 1, kGhostIface = 2;

 private:
  static int list_of(NodeState s);
  void insert(int level, int point, int list);
  void erase(int level, int point, int list);
  void sort_list(int level, int list);
  void build_stencils(const Hierarchy& h, int level, int list);

  std::vector<std::array<std::vector<int>, 3>> lists_;
  std::vector<std::vector<signed char>> filed_;  // list a point is filed under, -1 for none
  std::vector<std::vector<int>> slot_;           // its position in that list
  std::vector<std::array<std::vector<GhostStencil>, 2>> stencils_;  // [level][sub, iface]
};

}  // namespace mrsim
