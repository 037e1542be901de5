#include "io/vtk_tetra_cells.hpp"

namespace mrsim {

vtkSmartPointer<vtkCellArray> tetra_cells(const TetMesh& mesh, CellIds ids) {
  return uniform_cells<4>(static_cast<vtkIdType>(mesh.tets.size()),
                          static_cast<vtkIdType>(mesh.points.size()),
                          [&](vtkIdType t, int k) { return mesh.tets[t][k]; }, ids);
}

}  // namespace mrsim
