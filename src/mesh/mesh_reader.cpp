#include "mesh/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/vtk_module.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/medit_reader.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh/raw_mesh.hpp"
#include "mesh/tetgen_reader.hpp"

namespace mrsim {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool is_surface_extension(const std::string& ext) {
  return ext == ".stl" || ext == ".obj" || ext == ".off" || ext == ".ply";
}

RawMesh read_raw(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".msh") return read_gmsh(path);
  if (ext == ".vtu") return vtk_module().read_vtu(path);  // mesh/vtu_reader.hpp
  if (ext == ".mesh" || ext == ".meshb") return read_medit(path);
  if (ext == ".node" || ext == ".ele") return read_tetgen(path);
  if (is_surface_extension(ext))
    throw mesh_error(path, cat("is a surface mesh (", ext, "), but a tetrahedral volume mesh is needed here; "
                               "`mrsim mesh SURFACE` builds tet meshes from surfaces"));
  if (ext == ".vtk")
    throw mesh_error(path, "legacy VTK (.vtk) files are not supported: save the mesh as VTK XML (.vtu)");
  throw mesh_error(path, cat("unknown mesh file extension '", ext, "'; supported: .msh (gmsh 2.2/4.1), "
                             ".vtu (VTK XML), .mesh (Medit), .node/.ele (TetGen)"));
}

}  // namespace

double metres_per(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Metre: return 1.0;
    case LengthUnit::Millimetre: return 1e-3;
  }
  return 1.0;
}

TetMesh read_tet_mesh(const std::filesystem::path& path, LengthUnit unit, MeshReadReport* report) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw mesh_error(path, "file not found");
  return check_raw_mesh(read_raw(path), path, metres_per(unit), report);
}

}  // namespace mrsim
