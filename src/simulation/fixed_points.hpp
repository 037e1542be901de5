#pragma once
// Dirichlet vertices selected by box, half-space and id list (scenario `fixed`), per level.
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "scenario/scenario.hpp"

namespace mrsim {

/// Per level, 1 for every point selected by at least one region that applies to that level
/// (`level` -1 applies to all). Positions are compared with a tolerance of 1e-9 × the mesh's
/// bounding-box diagonal so that points on a box face are included. Throws InputError when a
/// region selects no point on any level it applies to, or names an id out of range; warns when
/// it selects nothing on one level only (a coarse mesh may have no vertex in a thin box).
std::vector<std::vector<std::uint8_t>> select_fixed_points(
    const std::vector<const TetMesh*>& levels, const std::vector<FixedRegion>& regions);

}  // namespace mrsim
