#pragma once
// The tets across each face of every tet: for walks from tet to tet towards a point.
#include <array>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

/// out[t][k]: the tet sharing t's face opposite its vertex k, or -1 on the boundary (and on a
/// face that more than two tets share, which a valid mesh does not have). O(T + P).
std::vector<std::array<int, 4>> tet_neighbours(const TetMesh& mesh);

}  // namespace mrsim
