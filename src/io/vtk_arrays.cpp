#include "io/vtk_arrays.hpp"

#include <cstring>

namespace mrsim {

vtkSmartPointer<vtkPoints> double_points(vtkIdType count) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  return points;
}

vtkSmartPointer<vtkPoints> deformed_points(std::span<const Vec3> rest,
                                           std::span<const Vec3> displacement) {
  auto points = double_points(static_cast<vtkIdType>(rest.size()));
  // Straight into the points' double storage, without a virtual call a point.
  double* xyz = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const Vec3 x = rest[i] + displacement[i];
    xyz[3 * i] = x.x();
    xyz[3 * i + 1] = x.y();
    xyz[3 * i + 2] = x.z();
  }
  return points;
}

vtkSmartPointer<vtkDoubleArray> vector_array(const char* name, std::span<const Vec3> values) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  // Vec3 is three contiguous doubles: one copy into VTK's (array-of-structures) storage.
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  if (!values.empty())
    std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(Vec3));
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
