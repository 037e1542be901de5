#pragma once
// Builds the nodal forces of a scenario load on the finest level: the total force spread over the
// boundary faces inside a box in proportion to their area (the consistent nodal forces of a
// uniform traction on linear triangles: a third of each face's share on each vertex).
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "scenario/scenario.hpp"
#include "simulation/surface_load.hpp"

namespace mrsim {

/// On the finest level's boundary faces whose centroid is in the box (within 1e-9 of the face
/// size). Throws InputError naming loads[index] when there is none.
SurfaceLoad distribute_surface_load(const TetMesh& finest, const SurfaceLoadSpec& spec,
                                    std::size_t index);

}  // namespace mrsim
