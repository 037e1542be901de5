#pragma once
// Each skin vertex bound by barycentric coordinates to a tet of every level, once at rest
// (method.md §6.2 point 1). A vertex outside a level's mesh (independent meshes of one object
// do not share their boundary) gets the nearest tet with signed coordinates: it is
// extrapolated, like the ghosts of §4.1 point 6.
#include <vector>

#include "contact/skin.hpp"
#include "hierarchy/level_links.hpp"
#include "hierarchy/tet_locator.hpp"

namespace mrsim {

struct SkinBinding {
  std::vector<std::vector<int>> tet;    // [level][skin vertex]
  std::vector<std::vector<Bary>> bary;  // [level][skin vertex], Σ = 1
};

SkinBinding bind_skin(const Skin& skin, const std::vector<const TetMesh*>& levels);
/// The same with each level's locator given (shared with the level links). When the skin is
/// the finest level's boundary, `finest_in_coarser` (the finest points' parent tets, located
/// by the same locator) answers for the level below the finest without locating again.
SkinBinding bind_skin(const Skin& skin, const std::vector<TetLocator>& levels,
                      const Embedding* finest_in_coarser = nullptr);

}  // namespace mrsim
