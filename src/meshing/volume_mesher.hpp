#pragma once
// One meshing attempt: the solid of a GeometrySource tetrahedralised by gmsh at a uniform
// target edge length, with single-threaded, seeded algorithms so that the same settings give
// the same mesh byte for byte. Returns the tets positively oriented, with only the points
// they use, numbered in gmsh's node order.
#include <string>

#include "mesh/tet_mesh.hpp"
#include "meshing/geometry_source.hpp"

namespace mrsim {

/// gmsh's 2-D and 3-D algorithm pairs (Debian's gmsh 4.8 lacks Netgen, hence the "Frontal"
/// 3-D algorithm and the Netgen optimiser). The size search uses Delaunay only: Hxt gives
/// slightly better tets but its output depends on the process's heap history.
enum class MeshAlgorithm {
  Hxt,       // 2-D Frontal-Delaunay + 3-D HXT
  Delaunay,  // 2-D Delaunay + 3-D Delaunay with a stricter optimisation threshold
};

std::string algorithm_name(MeshAlgorithm algorithm);

struct MeshSettings {
  double size = 0.0;  // target edge length (m)
  MeshAlgorithm algorithm = MeshAlgorithm::Hxt;
};

/// Throws GmshFailure when gmsh reports an error or returns no tetrahedron.
TetMesh mesh_solid(const GeometrySource& source, const MeshSettings& settings);

}  // namespace mrsim
