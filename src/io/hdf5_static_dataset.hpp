#pragma once
// Fixed-size datasets written once (rest positions, tets): contiguous, uncompressed, typed
// with mrsim's little-endian file types.
#include <hdf5.h>

#include <span>
#include <string>
#include <vector>

#include "io/hdf5_error.hpp"
#include "io/hdf5_types.hpp"

namespace mrsim::h5 {

/// Writes `data` (row-major, product(dims) elements of `memory_type`) as `name` under `parent`,
/// with a `units` attribute unless `units` is empty.
void write_static_dataset(hid_t parent, const std::string& name, hid_t file_type,
                          hid_t memory_type, const std::vector<hsize_t>& dims, const void* data,
                          const std::string& units, Where where);

template <class T>
void write_static_dataset(hid_t parent, const std::string& name, std::span<const T> values,
                          const std::vector<hsize_t>& dims, const std::string& units,
                          Where where) {
  write_static_dataset(parent, name, TypeOf<T>::file(), TypeOf<T>::memory(), dims, values.data(),
                       units, where);
}

}  // namespace mrsim::h5
