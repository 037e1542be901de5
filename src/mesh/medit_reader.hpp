#pragma once
// Medit ASCII .mesh (MeshVersionFormatted 1-4, Dimension 3): Vertices and Tetrahedra are read,
// surface and annotation sections (Triangles, Edges, Corners, Ridges, ...) skipped, other
// volume cells rejected. Keywords are case-insensitive; '#' starts a comment. Binary .meshb
// is rejected with a conversion hint.
#include <filesystem>

#include "mesh/raw_mesh.hpp"

namespace mrsim {

RawMesh read_medit(const std::filesystem::path& path);

}  // namespace mrsim
