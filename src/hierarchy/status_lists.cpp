#include "hierarchy/status_lists.hpp"

#include <algorithm>

namespace mrsim {

int StatusLists::list_of(NodeState s) {
  switch (s) {
    case NodeState::Active: return kActive;
    case NodeState::GhostSub: return kGhostSub;
    case NodeState::GhostIface: return kGhostIface;
    case NodeState::Inactive: return -1;
  }
  return -1;
}

StatusLists::StatusLists(const Hierarchy& h)
    : lists_(h.num_levels()), filed_(h.num_levels()), slot_(h.num_levels()) {
  for (int l = 0; l < h.num_levels(); ++l) {
    filed_[l].assign(h.num_points(l), -1);
    slot_[l].assign(h.num_points(l), -1);
    for (int p = 0; p < h.num_points(l); ++p) {
      const int which = list_of(h.state(l, p));
      if (which >= 0) insert(l, p, which);
    }
  }
}

void StatusLists::insert(int level, int point, int list) {
  auto& v = lists_[level][list];
  slot_[level][point] = static_cast<int>(v.size());
  filed_[level][point] = static_cast<signed char>(list);
  v.push_back(point);
}

void StatusLists::erase(int level, int point, int list) {
  auto& v = lists_[level][list];
  const int s = slot_[level][point];
  v[s] = v.back();  // swap-remove, O(1)
  slot_[level][v[s]] = s;
  v.pop_back();
  filed_[level][point] = -1;
  slot_[level][point] = -1;
}

void StatusLists::sort_list(int level, int list) {
  auto& v = lists_[level][list];
  std::sort(v.begin(), v.end());
  for (int s = 0; s < static_cast<int>(v.size()); ++s) slot_[level][v[s]] = s;
}

void StatusLists::update(const Hierarchy& h, const std::vector<std::pair<int, int>>& touched) {
  std::vector<std::array<bool, 3>> dirty(lists_.size(), {false, false, false});
  for (const auto& [l, p] : touched) {
    const int now = list_of(h.state(l, p));
    const int was = filed_[l][p];
    if (now == was) continue;
    if (was >= 0) {
      erase(l, p, was);
      dirty[l][was] = true;
    }
    if (now >= 0) {
      insert(l, p, now);
      dirty[l][now] = true;
    }
  }
  for (size_t l = 0; l < lists_.size(); ++l)
    for (int k = 0; k < 3; ++k)
      if (dirty[l][k]) sort_list(static_cast<int>(l), k);
}

std::size_t StatusLists::total(int which) const {
  std::size_t n = 0;
  for (const auto& level : lists_) n += level[which].size();
  return n;
}

}  // namespace mrsim
