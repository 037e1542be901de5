#pragma once
// The skin of a tet mesh: faces that belong to exactly one tet.
#include <array>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

using Face = std::array<int, 3>;

/// Boundary faces, each oriented with its normal pointing out of the mesh (tets positively
/// oriented, as every reader returns them), in the lexicographic order of their sorted vertex
/// ids. O(T + P).
std::vector<Face> boundary_faces(const TetMesh& mesh);

}  // namespace mrsim
