#include "io/vtk_arrays.hpp"

namespace mrsim {

vtkSmartPointer<vtkPoints> double_points(vtkIdType count) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
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

void add_time_value(vtkFieldData* data, double time) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName("TimeValue");
  array->SetNumberOfValues(1);
  array->SetValue(0, time);
  data->AddArray(array);
}

}  // namespace mrsim
