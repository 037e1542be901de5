#pragma once
// Energy-consistent coupling across levels (docs/hierarchy.md): a ghost's displacement is a
// linear function of active displacements, u_ghost = Σ w u_source (the interpolations of
// method.md §4.8), so the force a ghost receives from the tets it shares with active points is
// passed back to its sources with the same weights (the transpose, virtual work unchanged).
// The coupled stiffness is then Jᵀ K J: symmetric, and no interface mode can grow.
#include <vector>

#include "hierarchy/status_lists.hpp"

namespace mrsim {

/// Adds every ghost's force to its sources, in the reverse of the ghost update order:
/// interface ghosts fine -> coarse (pass B reversed), then subdivided ghosts coarse -> fine
/// (pass A reversed), so a chain of ghosts hands its force on until it reaches active points.
/// Serial and in list order: the result does not depend on the thread count. O(ghosts).
void transfer_ghost_forces(const Hierarchy& h, const StatusLists& lists, std::vector<Vec3*>& f);

/// Some ghosts per level, each list a subsequence of the level's StatusLists list.
struct GhostSelection {
  std::vector<const std::vector<int>*> iface, sub;  // [level]
};

/// The same transfer for the selected ghosts only (time levels: the ghosts whose force reaches
/// the particles integrated in a sub-step). A source receives exactly what the whole transfer
/// gives it when every ghost it depends on is selected, in the same order.
void transfer_ghost_forces(const Hierarchy& h, const GhostSelection& ghosts, std::vector<Vec3*>& f);

}  // namespace mrsim
