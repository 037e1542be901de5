#pragma once
// VTK arrays filled from the simulation's spans, shared by the level grids and the surface and
// tool blocks so that every block stores the same kinds of values the same way (float64
// vectors, exact-width integers, TimeValue). Internal to mrsim_io.
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <span>

#include "core/vec.hpp"

namespace mrsim {

/// Points in float64: float would lose the sub-micrometre displacements.
vtkSmartPointer<vtkPoints> double_points(vtkIdType count);
/// Points at rest + displacement (the deformed positions the frames show), as doubles.
vtkSmartPointer<vtkPoints> deformed_points(std::span<const Vec3> rest,
                                           std::span<const Vec3> displacement);

/// A 3-component float64 array, one tuple per value.
vtkSmartPointer<vtkDoubleArray> vector_array(const char* name, std::span<const Vec3> values);

/// One value per entry into a VTK array of the matching width (ArrayT::ValueType), e.g.
/// vtkSignedCharArray for int8 so that the XML says Int8.
template <class ArrayT, class T>
vtkSmartPointer<ArrayT> scalar_array(const char* name, std::span<const T> values) {
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));  // VTK's contiguous storage
  return array;
}

/// An N-component float64 array, one tuple per value, its components named.
template <std::size_t N>
vtkSmartPointer<vtkDoubleArray> tuple_array(const char* name,
                                            std::span<const std::array<double, N>> values,
                                            const char* const (&component_names)[N]) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(static_cast<int>(N));
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < N; ++k) array->SetComponentName(static_cast<vtkIdType>(k), component_names[k]);
  double* out = array->GetPointer(0);
  for (const std::array<double, N>& v : values) out = std::copy(v.begin(), v.end(), out);
  return array;
}

/// Adds `time` (s) as the field array TimeValue, the name ParaView reads when a single piece
/// is opened alone.
void add_time_value(vtkFieldData* data, double time);

}  // namespace mrsim
