#pragma once
// VTK XML UnstructuredGrid (.vtu), any encoding VTK reads (ascii, inline binary, appended raw
// or base64, zlib/lz4/lzma compressed). VTK_TETRA cells are kept; vertex, line and surface
// cells are skipped; other 3-D cells are rejected. Everything VTK does not check (lying
// counts, out-of-range point ids, inconsistent offsets) is checked here.
#include <filesystem>

#include "mesh/raw_mesh.hpp"

namespace mrsim {

RawMesh read_vtu(const std::filesystem::path& path);

}  // namespace mrsim
