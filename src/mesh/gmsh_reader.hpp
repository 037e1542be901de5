#pragma once
// gmsh .msh files: MSH 2.x and 4.1, ASCII and binary (either endianness). Linear tetrahedra
// (type 4) are the cells; points, lines and surface elements are skipped; other 3-D elements,
// MSH 4.0 and the legacy MSH 1 ($NOD/$ELM) are rejected with a message saying what to do.
#include <filesystem>

#include "mesh/raw_mesh.hpp"

namespace mrsim {

RawMesh read_gmsh(const std::filesystem::path& path);

}  // namespace mrsim
