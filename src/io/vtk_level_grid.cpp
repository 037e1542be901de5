#include "io/vtk_level_grid.hpp"
#include "io/vtk_tetra_cells.hpp"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSignedCharArray.h>

#include <span>

namespace mrsim {
namespace {

vtkSmartPointer<vtkPoints> deformed_points(const LevelFrameView& view) {
  const auto& rest = view.mesh->points;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();  // float would lose the sub-micrometre displacements
  points->SetNumberOfPoints(static_cast<vtkIdType>(rest.size()));
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const Vec3 x = rest[i] + view.displacement[i];
    points->SetPoint(static_cast<vtkIdType>(i), x.x(), x.y(), x.z());
  }
  return points;
}

vtkSmartPointer<vtkDoubleArray> vector_array(const char* name, std::span<const Vec3> values) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    array->SetTypedTuple(static_cast<vtkIdType>(i), values[i].data());
  }
  return array;
}

// Copies one scalar per point into a VTK array of the matching width (ArrayT::ValueType).
template <class ArrayT, class T>
vtkSmartPointer<ArrayT> scalar_array(const char* name, std::span<const T> values) {
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  return array;
}

void add_point_arrays(vtkPointData* data, const LevelFrameView& view) {
  data->AddArray(vector_array("displacement", view.displacement));
  data->AddArray(vector_array("velocity", view.velocity));
  data->AddArray(vector_array("force", view.force));
  data->AddArray(scalar_array<vtkSignedCharArray>("status", view.status));  // Int8 in XML
  data->AddArray(scalar_array<vtkIntArray>("time_level", view.time_level));
  data->AddArray(scalar_array<vtkDoubleArray>("criterion", view.criterion));
  data->AddArray(scalar_array<vtkDoubleArray>("mass", view.mass));
  // Displacement is the default vector so glyphs and Warp By Vector pick it without clicks.
  data->SetActiveVectors("displacement");
}

void add_time_value(vtkFieldData* data, double time) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName("TimeValue");  // the name ParaView looks for
  array->SetNumberOfValues(1);
  array->SetValue(0, time);
  data->AddArray(array);
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> make_level_grid(const LevelFrameView& view, double time) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(deformed_points(view));
  grid->SetCells(VTK_TETRA, tetra_cells(*view.mesh));
  add_point_arrays(grid->GetPointData(), view);
  add_time_value(grid->GetFieldData(), time);
  return grid;
}

}  // namespace mrsim
