#pragma once
// Ghost refresh in dependency order (method.md §4.8), after every integration step:
//   pass A, fine -> coarse: subdivided ghosts interpolate from their child tet (finer level);
//   pass B, coarse -> fine: interface ghosts interpolate from their parent tet (coarser level).
// Sources of each ghost are always refreshed before it (invariant I3), so there is no lag.
// Displacements and velocities are both interpolated (velocities enter the damping force).
#include <vector>

#include "hierarchy/status_lists.hpp"

namespace mrsim {

/// Per-level views of the state arrays the ghosts read and write.
struct LevelFields {
  Vec3* u = nullptr;
  Vec3* v = nullptr;
};

void update_ghosts(const Hierarchy& h, const StatusLists& lists, std::vector<LevelFields>& fields);

/// Barycentric interpolation of one point of `level` from a tet of `other` level. Inline: the
/// ghost refresh calls it twice per ghost and step, and out of line it was a call each time.
inline Vec3 interpolate(const Vec3* values, const Tet& tet, const Bary& b) {
  return b[0] * values[tet[0]] + b[1] * values[tet[1]] + b[2] * values[tet[2]] +
         b[3] * values[tet[3]];
}

/// Fills every *inactive* point with the displacement/velocity interpolated from its parent
/// tet (coarse to fine), so every level shows the whole deformed object (issue 4 point 4).
/// O(all points): for output frames only.
void interpolate_inactive(const Hierarchy& h, std::vector<LevelFields>& fields);

}  // namespace mrsim
