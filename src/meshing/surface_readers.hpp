#pragma once
// Readers of closed triangulated surfaces: STL (ascii and binary), OBJ (v / f, polygons
// fan-triangulated), OFF (polygons fan-triangulated) and PLY (ascii, binary little and big
// endian). gmsh reads only STL, and silently, so mrsim reads every format itself and reports
// malformed files as InputError naming the file and the line or byte. The readers only parse:
// geometric and topological checks are in surface_checks.hpp.
#include <filesystem>
#include <string>

#include "meshing/surface_mesh.hpp"

namespace mrsim {

/// Reads a surface by extension (.stl, .obj, .off, .ply, case-insensitive), in file units.
SurfaceMesh read_surface(const std::filesystem::path& path);

SurfaceMesh read_stl(const std::string& bytes, const std::filesystem::path& path);
SurfaceMesh read_obj(const std::string& bytes, const std::filesystem::path& path);
SurfaceMesh read_off(const std::string& bytes, const std::filesystem::path& path);
SurfaceMesh read_ply(const std::string& bytes, const std::filesystem::path& path);

/// Appends face `face_number` (1-based) with the given 0-based corners, fan-triangulated
/// around its first corner. Shared by the readers of polygon formats.
void add_polygon(SurfaceMesh& surface, const std::vector<int>& corners, int face_number);

}  // namespace mrsim
