#pragma once
// The tets of a mesh as a VTK cell array (VTK 9 offsets + connectivity layout, filled directly,
// no per-cell insertion). Shared by the frame writer and `mrsim mesh`'s level writer.
#include <vtkCellArray.h>
#include <vtkSmartPointer.h>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

vtkSmartPointer<vtkCellArray> tetra_cells(const TetMesh& mesh);

}  // namespace mrsim
