#pragma once
// Dirichlet vertices selected by box, half-space and id list (scenario `fixed`).
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "scenario/scenario.hpp"

namespace mrsim {

/// 1 for every point selected by at least one region. Positions are compared with a tolerance
/// of 1e-9 × the mesh's bounding-box diagonal so that points on a box face are included.
/// Throws InputError when a region selects no point or names an id out of range.
std::vector<std::uint8_t> select_fixed_points(const TetMesh& mesh,
                                              const std::vector<FixedRegion>& regions);

}  // namespace mrsim
