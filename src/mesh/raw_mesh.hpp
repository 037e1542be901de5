#pragma once
// What a format reader hands to the checks (mesh_check.hpp): the file's points and tets as
// found, in file units and file order, plus the file's own numbering so that every message
// about a vertex or a tet can name it the way the user's tools do (gmsh tags, 1-based Medit
// positions, TetGen indices, VTK cell ids).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

struct RawMesh {
  std::string format;                   // MeshReadReport::format
  std::vector<Vec3> points;             // file units, file order
  std::vector<Tet> tets;                // 0-based indices into `points`, orientation as found
  std::vector<std::int64_t> point_ids;  // the file's name of each point (same size as points)
  std::vector<std::int64_t> tet_ids;    // the file's name of each tet (same size as tets)
  std::string point_noun = "vertex";    // "node" (gmsh, TetGen), "point" (VTK)...
  std::string tet_noun = "tetrahedron"; // "element" (gmsh), "cell" (VTK)
  std::map<std::string, std::size_t> ignored;  // lower-dimensional cells skipped: "triangles" -> 320
};

}  // namespace mrsim
