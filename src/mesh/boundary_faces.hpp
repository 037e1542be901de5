#pragma once
// The skin of a tet mesh: faces that belong to exactly one tet.
#include <array>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

using Face = std::array<int, 3>;

/// Boundary faces, each oriented with its normal pointing out of the mesh (tets positively
/// oriented, as every reader returns them), in a deterministic order. O(T log T).
std::vector<Face> boundary_faces(const TetMesh& mesh);

/// The same faces in the same order, sorting the vertex triples themselves: what
/// boundary_faces() does for meshes of 2^21 points or more (it packs each triple into 64 bits
/// below that).
std::vector<Face> boundary_faces_by_triples(const TetMesh& mesh);

}  // namespace mrsim
