#pragma once
// TetGen .node + .ele pairs (TetGen manual, section 5.2). `path` may name either file; the
// sibling with the other extension must exist. Nodes are numbered from 0 or 1 (the first
// index in .node decides); '#' comments, point attributes, boundary markers and region
// attributes are accepted and ignored. Only 4-node tetrahedra (no -o2 output).
#include <filesystem>

#include "mesh/raw_mesh.hpp"

namespace mrsim {

RawMesh read_tetgen(const std::filesystem::path& path);

}  // namespace mrsim
