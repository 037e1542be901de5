#pragma once
// The checks every mesh goes through after its format reader, whatever the format: finite
// coordinates, valid and distinct tet vertices, no degenerate tet; then unit conversion,
// reorientation of inverted tets and removal of unused vertices (each with one warning).
#include <filesystem>

#include "mesh/mesh_reader.hpp"
#include "mesh/raw_mesh.hpp"

namespace mrsim {

/// Smallest accepted tet quality |6V| / (longest edge)^3. Scale-free, so the same threshold
/// holds in metres and millimetres; a regular tet scores 1/sqrt(2), CGAL slivers ~1e-3.
inline constexpr double kMinTetQuality = 1e-8;

/// Validates `raw` (read from `path`), scales it by `metres_per_unit` and returns the mesh
/// mrsim simulates. Throws InputError naming the file and the offending vertex or tet.
/// Warnings go to warn() and, when `report` is given, into report->warnings.
TetMesh check_raw_mesh(RawMesh raw, const std::filesystem::path& path, double metres_per_unit,
                       MeshReadReport* report);

}  // namespace mrsim
