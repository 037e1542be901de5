#pragma once
// Static links between consecutive levels (method.md §4.2–4.3), computed once at rest:
// for every point, its parent tet (coarser level) and child tet (finer level) with barycentric
// coordinates; the parent/child tree of Voronoi regions; and for every coarse point the sets
// that a split activates (children ∪ child-tet vertices, the §4.6 fix) and makes ghosts
// (their neighbours).
#include <array>
#include <vector>

#include "hierarchy/csr_lists.hpp"
#include "hierarchy/tet_locator.hpp"
#include "physics/point_adjacency.hpp"

namespace mrsim {

using Bary = std::array<double, 4>;

/// Where a point of one level sits in a tet of another level.
struct Embedding {
  std::vector<int> tet;    // -1 when there is no such level
  std::vector<Bary> bary;  // signed when the point is outside that mesh
  // The four vertices of `tet` (-1 without one): the ghost refresh and the force transfer of
  // every step read a point's sources here rather than through the tet.
  std::vector<std::array<int, 4>> source;
};

struct LevelLinks {
  Embedding parent_tet;   // in level ℓ-1
  Embedding child_tet;    // in level ℓ+1
  std::vector<int> parent;  // level ℓ-1 point whose Voronoi region holds X; -1 at level 0
  CsrLists children;        // level ℓ+1 points whose parent is this point
  CsrLists active_set;      // level ℓ+1: children ∪ vertices(child tet)
  CsrLists ghost_set;       // level ℓ+1: neighbours of active_set, not in it
  CsrLists dependents;      // level ℓ+1 points whose parent tet has this point as a vertex
};

struct HierarchyLevel {
  const TetMesh* mesh = nullptr;
  const PointAdjacency* adj = nullptr;
};


/// Links for every level; O(N log N)-like with a spatial grid per level.
std::vector<LevelLinks> build_level_links(const std::vector<HierarchyLevel>& levels);
/// The same with each level's locator given (`locators[l]` over `levels[l].mesh`), when the
/// caller locates other points in the levels too (the skin binding).
std::vector<LevelLinks> build_level_links(const std::vector<HierarchyLevel>& levels,
                                          const std::vector<TetLocator>& locators);

}  // namespace mrsim
