#pragma once
// Remeshing a curved surface at a coarse size puts the new vertices on the surface, so the
// coarse solid is inscribed in the original and too small (-40 % for a 30-tet liver). The
// levels of one object must weigh the same (the multiresolution model lumps mass per level),
// so the boundary points of each level are moved along their normals by one common offset
// chosen to restore the input's enclosed volume. Interior points stay; an offset that would
// invert a tet is reduced until none does.
#include "mesh/tet_mesh.hpp"

namespace mrsim {

/// Moves boundary points of `mesh` by a common normal offset so that its volume becomes
/// `target_volume`; returns the offset applied (m, positive outward).
double match_volume(TetMesh& mesh, double target_volume);

}  // namespace mrsim
