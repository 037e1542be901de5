#pragma once
// Structured tet meshes of a box (Kuhn 6-tet split of each hexahedral cell), for tests,
// benchmarks and validation runs. All tets positively oriented.
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

TetMesh make_box_mesh(const Vec3& min, const Vec3& max, int nx, int ny, int nz);

/// The same box with cells of varying width along x: `x_widths` (relative, > 0) scaled to the
/// box length; ny x nz uniform cells across. Graded meshes for the time-level tests and bench.
TetMesh make_graded_box_mesh(const Vec3& min, const Vec3& max, const std::vector<double>& x_widths,
                             int ny, int nz);

/// Cells of varying width along every axis (relative widths, > 0): meshes fine under a tool
/// and coarse away from it, for the contact validation.
TetMesh make_graded_box_mesh(const Vec3& min, const Vec3& max, const std::vector<double>& x_widths,
                             const std::vector<double>& y_widths,
                             const std::vector<double>& z_widths);

}  // namespace mrsim
