#pragma once
// Structured tet meshes of a box (Kuhn 6-tet split of each hexahedral cell), for tests,
// benchmarks and validation runs. All tets positively oriented.
#include "mesh/tet_mesh.hpp"

namespace mrsim {

TetMesh make_box_mesh(const Vec3& min, const Vec3& max, int nx, int ny, int nz);

}  // namespace mrsim
