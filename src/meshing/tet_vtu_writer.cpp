#include "meshing/tet_vtu_writer.hpp"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkIdTypeArray.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/vtk_error_capture.hpp"
#include "io/vtk_tetra_cells.hpp"

namespace mrsim {
namespace {

vtkSmartPointer<vtkUnstructuredGrid> make_grid(const TetMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.points[i].data());
  }
  const auto cells = tetra_cells(mesh);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(VTK_TETRA, cells);
  return grid;
}

}  // namespace

void write_tet_vtu(const std::filesystem::path& file, const TetMesh& mesh) {
  auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  writer->SetInputData(make_grid(mesh));
  writer->SetCompressorTypeToZLib();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  writer->WriteToOutputStringOn();  // then written atomically: no half-written level on disk
  VtkErrorCapture errors;
  if (writer->Write() != 1 || errors.any()) {
    throw RunError("cannot write " + file.string() + ": " + errors.summary());
  }
  write_file_atomically(file, writer->GetOutputString());
}

}  // namespace mrsim
