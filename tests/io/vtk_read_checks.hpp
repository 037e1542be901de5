#pragma once
// Reading back what the VTK writers wrote: a .vtm, and element-by-element checks of named
// point, cell or field data arrays (all derive from vtkFieldData).
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataReader.h>

#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "core/vec.hpp"

namespace mrsim::test {

inline vtkSmartPointer<vtkMultiBlockDataSet> read_vtm(const std::filesystem::path& file) {
  auto reader = vtkSmartPointer<vtkXMLMultiBlockDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  return vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
}

inline void expect_vectors(vtkFieldData* data, const char* name,
                           const std::vector<Vec3>& expected) {
  vtkDataArray* array = data->GetArray(name);
  ASSERT_NE(array, nullptr) << name;
  EXPECT_EQ(array->GetDataType(), VTK_DOUBLE) << name;
  ASSERT_EQ(array->GetNumberOfComponents(), 3) << name;
  ASSERT_EQ(array->GetNumberOfTuples(), static_cast<vtkIdType>(expected.size())) << name;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(array->GetComponent(static_cast<vtkIdType>(i), c), expected[i][c])
          << name << " tuple " << i << " component " << c;
    }
  }
}

template <class T>
inline void expect_scalars(vtkFieldData* data, const char* name, int vtk_type,
                           const std::vector<T>& expected) {
  vtkDataArray* array = data->GetArray(name);
  ASSERT_NE(array, nullptr) << name;
  EXPECT_EQ(array->GetDataType(), vtk_type) << name;
  ASSERT_EQ(array->GetNumberOfComponents(), 1) << name;
  ASSERT_EQ(array->GetNumberOfTuples(), static_cast<vtkIdType>(expected.size())) << name;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_EQ(array->GetComponent(static_cast<vtkIdType>(i), 0), static_cast<double>(expected[i]))
        << name << " tuple " << i;
  }
}

}  // namespace mrsim::test
