#pragma once
// Writes a rest-state tet mesh as VTK XML UnstructuredGrid: double-precision points (metres),
// VTK_TETRA cells, appended raw binary, zlib-compressed. This is the file the scenarios list
// and mrsim's mesh reader loads. The same mesh always gives the same bytes.
#include <filesystem>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

/// Replaces `file` atomically; throws RunError naming the file on failure.
void write_tet_vtu(const std::filesystem::path& file, const TetMesh& mesh);

}  // namespace mrsim
