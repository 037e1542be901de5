#pragma once
// Reading back what mrsim wrote (checkpoints, a log.h5 to resume): typed whole datasets and
// scalar attributes, with the shape checked. Failures throw RunError naming file and object
// (io/hdf5_error.hpp); the caller decides whether that is an input error.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/hdf5_error.hpp"
#include "io/hdf5_types.hpp"

namespace mrsim::h5 {

bool has_link(hid_t parent, const std::string& name, Where where);
std::string read_string_attribute(hid_t object, const char* name, Where where);
std::int64_t read_int64_attribute(hid_t object, const char* name, Where where);

/// Dimensions of dataset `name` under `parent`.
std::vector<hsize_t> dataset_dims(hid_t parent, const std::string& name, Where where);

/// Every element of dataset `name` (row-major), converted to T by HDF5. Throws RunError when
/// its dimensions are not `dims`.
void read_dataset(hid_t parent, const std::string& name, hid_t memory_type, void* out,
                  const std::vector<hsize_t>& dims, Where where);

template <class T>
std::vector<T> read_dataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
                            Where where) {
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  std::vector<T> values(n);
  read_dataset(parent, name, TypeOf<T>::memory(), values.data(), dims, where);
  return values;
}

}  // namespace mrsim::h5
