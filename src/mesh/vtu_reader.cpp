#include "mesh/vtu_reader.hpp"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <array>
#include <new>
#include <string>

#include "mesh/mesh_input.hpp"
#include "mesh/vtk_message_capture.hpp"
#include "mesh/vtu_header_check.hpp"

namespace mrsim {
namespace {

vtkSmartPointer<vtkUnstructuredGrid> run_vtk_reader(const std::filesystem::path& path) {
  VtkMessageCapture capture;  // declared first: outlives the reader that reports to it
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  capture.watch(reader);
  reader->SetFileName(path.string().c_str());
  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    // A size in the binary headers (e.g. compressed block sizes) can still lie.
    throw mesh_error(path, "VTK ran out of memory while reading: a size in the file is wrong (corrupt file)");
  } catch (const std::exception& e) {
    throw mesh_error(path, cat("VTK failed to read the file: ", e.what()));
  }
  if (!capture.errors().empty() || reader->GetErrorCode() != 0) {
    const std::string first = capture.errors().empty() ? "error code " + std::to_string(reader->GetErrorCode())
                                                        : capture.errors().front();
    throw mesh_error(path, cat("VTK could not read the file (truncated or corrupt?): ", first));
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (!grid) throw mesh_error(path, "VTK returned no dataset");
  return grid;
}

struct CellKind {
  int dim = -1;          // -1: unknown type
  std::string name;      // "vtkHexahedron"
};

CellKind describe(int type) {
  CellKind k;
  const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
  if (!name || std::string_view(name) == "UnknownClass") return k;
  k.name = name;
  vtkSmartPointer<vtkCell> cell;
  cell.TakeReference(vtkGenericCell::InstantiateCell(type));
  k.dim = cell ? cell->GetCellDimension() : -1;
  return k;
}

std::string ignored_name(int type, const CellKind& k) {
  switch (type) {
    case VTK_EMPTY_CELL: return "empty cells";
    case VTK_VERTEX: case VTK_POLY_VERTEX: return "vertex cells";
    case VTK_LINE: case VTK_POLY_LINE: return "lines";
    case VTK_TRIANGLE: return "triangles";
    case VTK_QUAD: case VTK_PIXEL: return "quads";
    case VTK_POLYGON: return "polygons";
    case VTK_TRIANGLE_STRIP: return "triangle strips";
    default: return cat(k.name, " cells");
  }
}

// Decides once per cell type: keep (tetra), skip (lower dimension) or reject (with why).
class CellTypePolicy {
 public:
  bool keep(int type, vtkIdType cell, const std::filesystem::path& path, RawMesh& raw) {
    if (type == VTK_TETRA) return true;
    if (!known_[type]) {
      kinds_[type] = describe(type);
      known_[type] = true;
    }
    const CellKind& k = kinds_[type];
    if (k.dim < 0) throw mesh_error(path, cat("cell ", cell, " has unknown VTK cell type ", type));
    if (k.dim == 3) {
      const bool tet = k.name.find("Tetra") != std::string::npos;
      throw mesh_error(path, cat("cell ", cell, ": ", k.name, " cells (VTK cell type ", type, ") are not supported",
                                 tet ? "; export linear elements (VTK_TETRA, 4 points)"
                                     : ": mrsim simulates tetrahedral meshes only"));
    }
    ++raw.ignored[ignored_name(type, k)];
    return false;
  }

 private:
  std::array<CellKind, 256> kinds_;
  std::array<bool, 256> known_{};
};

// Offsets must start at 0, never decrease and end at the connectivity size, or walking the
// cells would read outside the connectivity array.
void check_cell_arrays(vtkUnstructuredGrid* grid, const std::filesystem::path& path) {
  const vtkIdType n = grid->GetNumberOfCells();
  vtkCellArray* cells = grid->GetCells();
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (n == 0) return;
  if (!cells || !types || types->GetNumberOfTuples() != n)
    throw mesh_error(path, "the cell arrays are missing or inconsistent (corrupt file)");
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* conn = cells->GetConnectivityArray();
  if (!offsets || !conn || offsets->GetNumberOfTuples() != n + 1 || offsets->GetTuple1(0) != 0)
    throw mesh_error(path, "the cell offsets are missing or inconsistent (corrupt file)");
  double previous = 0;
  for (vtkIdType c = 1; c <= n; ++c) {
    const double o = offsets->GetTuple1(c);
    if (o < previous) throw mesh_error(path, cat("cell ", c - 1, " has a negative size (corrupt offsets array)"));
    previous = o;
  }
  if (previous != static_cast<double>(conn->GetNumberOfTuples()))
    throw mesh_error(path, "the cell offsets do not match the connectivity array (corrupt file)");
}

void extract_points(vtkUnstructuredGrid* grid, RawMesh& raw) {
  const vtkIdType n = grid->GetNumberOfPoints();
  raw.points.resize(static_cast<std::size_t>(n));
  raw.point_ids.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) {
    grid->GetPoints()->GetPoint(i, raw.points[static_cast<std::size_t>(i)].data());
    raw.point_ids[static_cast<std::size_t>(i)] = i;
  }
}

void extract_tets(vtkUnstructuredGrid* grid, const std::filesystem::path& path, RawMesh& raw) {
  check_cell_arrays(grid, path);
  const vtkIdType n = grid->GetNumberOfCells();
  if (n == 0) return;
  const vtkIdType points = grid->GetNumberOfPoints();
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  vtkNew<vtkIdList> ids;  // exact integer ids, whatever the storage type of the file
  CellTypePolicy policy;
  for (vtkIdType c = 0; c < n; ++c) {
    grid->GetCells()->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      if (ids->GetId(k) < 0 || ids->GetId(k) >= points)
        throw mesh_error(path, cat("cell ", c, " refers to point ", ids->GetId(k), ", but the file has ", points,
                                   " points (numbered from 0)"));
    if (!policy.keep(types->GetValue(c), c, path, raw)) continue;
    if (ids->GetNumberOfIds() != 4)
      throw mesh_error(path, cat("cell ", c, " is a tetrahedron with ", ids->GetNumberOfIds(), " points"));
    raw.tets.push_back({static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
                        static_cast<int>(ids->GetId(2)), static_cast<int>(ids->GetId(3))});
    raw.tet_ids.push_back(c);
  }
}

}  // namespace

RawMesh read_vtu(const std::filesystem::path& path) {
  const VtuDeclared header = check_vtu_header(read_whole_file(path), path);
  vtkSmartPointer<vtkUnstructuredGrid> grid = run_vtk_reader(path);
  // VTK fills what it could not read with nothing: compare with what the file declared.
  if (grid->GetNumberOfPoints() != header.points || grid->GetNumberOfCells() != header.cells)
    throw mesh_error(path, cat("VTK read ", grid->GetNumberOfPoints(), " points and ", grid->GetNumberOfCells(),
                               " cells, but the file declares ", header.points, " and ", header.cells,
                               " (truncated or corrupt file)"));
  RawMesh raw;
  raw.format = "vtu";
  raw.point_noun = "point";
  raw.tet_noun = "cell";
  if (header.points > 0 && !grid->GetPoints()) throw mesh_error(path, "the file has no Points array");
  if (header.points > 0) extract_points(grid, raw);
  extract_tets(grid, path, raw);
  return raw;
}

}  // namespace mrsim
