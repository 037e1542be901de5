#include "io/vtk_tetra_cells.hpp"

#include <vtkIdTypeArray.h>

namespace mrsim {

vtkSmartPointer<vtkCellArray> tetra_cells(const TetMesh& mesh) {
  const auto count = static_cast<vtkIdType>(mesh.tets.size());
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(count + 1);
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfValues(4 * count);
  for (vtkIdType t = 0; t < count; ++t) {
    offsets->SetValue(t, 4 * t);
    for (int c = 0; c < 4; ++c) connectivity->SetValue(4 * t + c, mesh.tets[t][c]);
  }
  offsets->SetValue(count, 4 * count);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

}  // namespace mrsim
