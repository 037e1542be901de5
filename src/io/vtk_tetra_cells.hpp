#pragma once
// Cells as VTK cell arrays (VTK 9 offsets + connectivity layout, filled directly, no per-cell
// insertion): the tets of a mesh, shared by the frame writer (compact ids) and `mrsim mesh`'s
// level writer (wide ids), and the uniform cells (triangles) of the surface blocks.
#include <vtkCellArray.h>
#include <vtkIdTypeArray.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>

#include <cstdint>
#include <limits>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

/// How a cell array stores its offsets and connectivity.
enum class CellIds {
  Compact,  // 32 bits when every offset and index fits, else VTK's 64-bit ids
  Wide      // VTK's 64-bit ids always
};

/// `cells` cells of N corners each; corner(c, k) is the point index of corner k of cell c.
/// Compact is for the frames: their connectivity then costs half the bytes to compress and write
/// (on liver_probe 16 % less work in the XML writer); VTK and ParaView read both.
template <int N, class Corner>
vtkSmartPointer<vtkCellArray> uniform_cells(vtkIdType cells, vtkIdType points, Corner corner,
                                            CellIds ids = CellIds::Compact) {
  auto fill = [&](auto offsets, auto connectivity) {
    offsets->SetNumberOfValues(cells + 1);
    connectivity->SetNumberOfValues(N * cells);
    for (vtkIdType c = 0; c <= cells; ++c) offsets->SetValue(c, N * c);
    for (vtkIdType c = 0; c < cells; ++c)
      for (int k = 0; k < N; ++k) connectivity->SetValue(N * c + k, corner(c, k));
    auto array = vtkSmartPointer<vtkCellArray>::New();
    array->SetData(offsets, connectivity);
    return array;
  };
  constexpr vtkIdType kMax = std::numeric_limits<std::int32_t>::max();
  if (ids == CellIds::Compact && N * cells <= kMax && points <= kMax)
    return fill(vtkSmartPointer<vtkTypeInt32Array>::New(), vtkSmartPointer<vtkTypeInt32Array>::New());
  return fill(vtkSmartPointer<vtkIdTypeArray>::New(), vtkSmartPointer<vtkIdTypeArray>::New());
}

vtkSmartPointer<vtkCellArray> tetra_cells(const TetMesh& mesh, CellIds ids = CellIds::Compact);

}  // namespace mrsim
