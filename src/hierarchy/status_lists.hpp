#pragma once
// Working lists of the points of each level by status (method.md §4.2: "per time level a list
// of active points"; §4.8: ghosts per level in update order). The simulation loops over these,
// so a step costs O(active + ghosts), never O(all points). Updated from Hierarchy::take_touched.
#include <array>
#include <vector>

#include "hierarchy/hierarchy.hpp"

namespace mrsim {

class StatusLists {
 public:
  explicit StatusLists(const Hierarchy& h);
  /// Re-files the touched points under their current status: O(touched) plus a sort of each
  /// list that changed (once per display frame, not per step).
  void update(const Hierarchy& h, const std::vector<std::pair<int, int>>& touched);

  const std::vector<int>& active(int level) const { return lists_[level][kActive]; }
  const std::vector<int>& ghost_sub(int level) const { return lists_[level][kGhostSub]; }
  const std::vector<int>& ghost_iface(int level) const { return lists_[level][kGhostIface]; }
  /// Lists are kept sorted by point index after update(): iteration order is deterministic
  /// and memory access follows the mesh numbering.
  std::size_t total(int which) const;

  static constexpr int kActive = 0, kGhostSub = 1, kGhostIface = 2;

 private:
  static int list_of(NodeState s);
  void insert(int level, int point, int list);
  void erase(int level, int point, int list);
  void sort_list(int level, int list);

  std::vector<std::array<std::vector<int>, 3>> lists_;
  std::vector<std::vector<signed char>> filed_;  // list a point is filed under, -1 for none
  std::vector<std::vector<int>> slot_;           // its position in that list
};

}  // namespace mrsim
