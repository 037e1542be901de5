#include "hierarchy/hierarchy.hpp"

#include <sstream>
#include <stdexcept>

namespace mrsim {

const char* node_state_name(NodeState s) {
  switch (s) {
    case NodeState::Inactive: return "inactive";
    case NodeState::Active: return "active";
    case NodeState::GhostSub: return "ghost(subdivided)";
    case NodeState::GhostIface: return "ghost(interface)";
  }
  return "?";
}

Hierarchy::Hierarchy(std::vector<HierarchyLevel> levels, std::vector<LevelLinks> links)
    : levels_(std::move(levels)), links_(std::move(links)), flags_(levels_.size()) {
  for (size_t l = 0; l < levels_.size(); ++l) {
    const size_t n = levels_[l].mesh->points.size();
    flags_[l].subdivided.assign(n, 0);
    flags_[l].support.assign(n, 0);
    flags_[l].active_ref.assign(n, 0);
    flags_[l].ghost_ref.assign(n, 0);
  }
}

void Hierarchy::restore(std::vector<HierarchyCounters> counters) {
  if (counters.size() != flags_.size())
    throw std::invalid_argument("Hierarchy::restore: " + std::to_string(counters.size()) +
                                " levels for a hierarchy of " + std::to_string(flags_.size()));
  for (size_t l = 0; l < flags_.size(); ++l) {
    const HierarchyCounters& c = counters[l];
    const size_t n = flags_[l].subdivided.size();
    if (c.subdivided.size() != n || c.support.size() != n || c.active_ref.size() != n ||
        c.ghost_ref.size() != n)
      throw std::invalid_argument("Hierarchy::restore: level " + std::to_string(l) +
                                  " counters do not have one entry per point");
  }
  std::swap(flags_, counters);
  if (const std::vector<std::string> broken = check_invariants(); !broken.empty()) {
    std::swap(flags_, counters);  // refused: the hierarchy stays as it was
    throw std::runtime_error("Hierarchy::restore: the counters break an invariant: " +
                             broken.front());
  }
  touched_.clear();
  for (int l = 0; l < num_levels(); ++l)
    for (int p = 0; p < num_points(l); ++p) touch(l, p);
}

bool Hierarchy::can_split(int l, int p) const {
  return l + 1 < num_levels() && state(l, p) == NodeState::Active &&
         !links_[l].children.row(p).empty();
}

bool Hierarchy::can_merge(int l, int p) const {
  if (!flags_[l].subdivided[p]) return false;
  for (int a : links_[l].active_set.row(p))
    if (flags_[l + 1].subdivided[a]) return false;
  return true;
}

// A GhostIface interpolates from its parent tet: make every vertex of it evaluable, adding
// support ghosts upward until a level that is really simulated there (§4.4). Level-0 points
// are never inactive, so this terminates.
void Hierarchy::ensure_resolvable(int l, int g, std::vector<std::pair<int, int>>* woken) {
  if (l == 0) return;
  const int t = links_[l].parent_tet.tet[g];
  for (int q : levels_[l - 1].mesh->tets[t]) {
    if (state(l - 1, q) != NodeState::Inactive) continue;
    flags_[l - 1].support[q] = 1;
    touch(l - 1, q);
    if (woken) woken->emplace_back(l - 1, q);
    ensure_resolvable(l - 1, q, woken);
  }
}

std::vector<std::pair<int, int>> Hierarchy::split(int l, int p) {
  std::vector<std::pair<int, int>> woken;
  flags_[l].subdivided[p] = 1;
  touch(l, p);
  Flags& fine = flags_[l + 1];
  for (int a : links_[l].active_set.row(p)) {
    if (state(l + 1, a) == NodeState::Inactive) woken.emplace_back(l + 1, a);
    ++fine.active_ref[a];
    touch(l + 1, a);
  }
  for (int g : links_[l].ghost_set.row(p)) {
    if (state(l + 1, g) == NodeState::Inactive) woken.emplace_back(l + 1, g);
    ++fine.ghost_ref[g];
    touch(l + 1, g);
    if (state(l + 1, g) == NodeState::GhostIface) ensure_resolvable(l + 1, g, &woken);
  }
  return woken;
}

void Hierarchy::merge(int l, int p) {
  flags_[l].subdivided[p] = 0;
  touch(l, p);
  Flags& fine = flags_[l + 1];
  for (int a : links_[l].active_set.row(p)) {
    --fine.active_ref[a];
    touch(l + 1, a);
  }
  for (int g : links_[l].ghost_set.row(p)) {
    --fine.ghost_ref[g];
    touch(l + 1, g);
  }
  // Points of the former sets that stay needed as ghosts must stay resolvable, and a point
  // that fell inactive while a finer interface ghost still interpolates from it stays as
  // support (the source's GC would otherwise leave that ghost without data until the frame end).
  auto keep = [&](int a) {
    if (state(l + 1, a) == NodeState::Inactive && l + 2 < num_levels())
      for (int g : links_[l + 1].dependents.row(a))
        if (state(l + 2, g) == NodeState::GhostIface) {
          fine.support[a] = 1;
          break;
        }
    if (state(l + 1, a) == NodeState::GhostIface) ensure_resolvable(l + 1, a, nullptr);
  };
  for (int a : links_[l].active_set.row(p)) keep(a);
  for (int g : links_[l].ghost_set.row(p)) keep(g);
}

int Hierarchy::collect_garbage() {
  int released = 0;
  std::vector<std::vector<std::uint8_t>> before(flags_.size());
  for (size_t l = 0; l < flags_.size(); ++l) {
    before[l] = flags_[l].support;
    std::fill(flags_[l].support.begin(), flags_[l].support.end(), 0);
  }
  // Fine to coarse, so a support mark made at level l-1 is seen when level l-1 is scanned.
  for (int l = num_levels() - 1; l >= 1; --l)
    for (int g = 0; g < num_points(l); ++g)
      if (state(l, g) == NodeState::GhostIface)
        for (int q : levels_[l - 1].mesh->tets[links_[l].parent_tet.tet[g]])
          if (state(l - 1, q) == NodeState::Inactive) flags_[l - 1].support[q] = 1;
  for (size_t l = 0; l < flags_.size(); ++l)
    for (size_t p = 0; p < before[l].size(); ++p)
      if (before[l][p] != flags_[l].support[p]) {
        released += before[l][p];
        touch(static_cast<int>(l), static_cast<int>(p));
      }
  return released;
}

std::int64_t Hierarchy::count(int l, NodeState s) const {
  std::int64_t c = 0;
  for (int p = 0; p < num_points(l); ++p) c += state(l, p) == s;
  return c;
}

void Hierarchy::check_point(int l, int p, std::vector<std::string>& out) const {
  auto fail = [&](const std::string& what) {
    std::ostringstream os;
    os << "level " << l << " point " << p << " (" << node_state_name(state(l, p)) << "): " << what;
    out.push_back(os.str());
  };
  const NodeState s = state(l, p);
  if (l == 0 && s != NodeState::Active && s != NodeState::GhostSub) fail("I1 level-0 not covered");
  if (s == NodeState::Active) {
    const PointAdjacency& adj = *levels_[l].adj;
    for (int e = adj.nbr_start[p]; e < adj.nbr_start[p + 1]; ++e)
      if (state(l, adj.nbr[e]) == NodeState::Inactive) fail("I2 inactive neighbour");
  }
  if (s == NodeState::GhostSub) {
    for (int q : levels_[l + 1].mesh->tets[links_[l].child_tet.tet[p]]) {
      const NodeState sq = state(l + 1, q);
      if (sq != NodeState::Active && sq != NodeState::GhostSub) fail("I3 child tet not simulated");
    }
    for (int a : links_[l].active_set.row(p)) {
      const NodeState sa = state(l + 1, a);
      if (sa != NodeState::Active && sa != NodeState::GhostSub) fail("I1 active set not covered");
    }
  }
  if (s == NodeState::GhostIface)
    for (int q : levels_[l - 1].mesh->tets[links_[l].parent_tet.tet[p]])
      if (state(l - 1, q) == NodeState::Inactive) fail("I3 parent tet has an inactive vertex");
}

std::vector<std::string> Hierarchy::check_invariants() const {
  std::vector<std::string> out;
  for (int l = 0; l < num_levels(); ++l)
    for (int p = 0; p < num_points(l); ++p) check_point(l, p, out);
  // I5: counters equal what the subdivided points imply.
  for (int l = 0; l + 1 < num_levels(); ++l) {
    std::vector<int> act(num_points(l + 1), 0), gho(num_points(l + 1), 0);
    for (int p = 0; p < num_points(l); ++p)
      if (flags_[l].subdivided[p]) {
        for (int a : links_[l].active_set.row(p)) ++act[a];
        for (int g : links_[l].ghost_set.row(p)) ++gho[g];
      }
    for (int q = 0; q < num_points(l + 1); ++q)
      if (act[q] != flags_[l + 1].active_ref[q] || gho[q] != flags_[l + 1].ghost_ref[q]) {
        std::ostringstream os;
        os << "level " << l + 1 << " point " << q << ": I5 counters differ from the splits";
        out.push_back(os.str());
      }
  }
  return out;
}

}  // namespace mrsim
