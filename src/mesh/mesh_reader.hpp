#pragma once
// Entry point of mesh input (issue 2 point 4): dispatch on the file extension, read, convert
// units, check and repair orientation. Bad input throws InputError naming the file.
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

enum class LengthUnit { Metre, Millimetre };

/// Factor that converts a length in `unit` to metres.
double metres_per(LengthUnit unit);

struct MeshReadReport {
  std::string format;               // "gmsh-2.2-ascii", "gmsh-4.1-binary", "vtu", "medit", "tetgen"
  int reoriented_tets = 0;          // inverted tets whose orientation was flipped
  int removed_vertices = 0;         // vertices used by no tet, dropped
  std::vector<int> kept_vertices;   // loaded vertex index -> 0-based position in the file
  std::vector<std::string> warnings;  // for the caller to print (no report: warn() prints them)
  std::vector<std::string> notes;     // not printed: "ignored 64 triangles"
};

/// Reads a tet-only mesh (.msh, .vtu, .mesh, .node/.ele) and returns it in metres with every
/// tet positively oriented. Throws InputError for unreadable, inconsistent or degenerate meshes.
TetMesh read_tet_mesh(const std::filesystem::path& path, LengthUnit unit,
                      MeshReadReport* report = nullptr);

}  // namespace mrsim
