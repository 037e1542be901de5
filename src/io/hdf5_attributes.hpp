#pragma once
// Scalar attributes on HDF5 objects: strings (variable-length UTF-8, read back as `str` by
// h5py) and integers.
#include <hdf5.h>

#include <cstdint>
#include <string_view>

#include "io/hdf5_error.hpp"

namespace mrsim::h5 {

/// Creates, or overwrites, attribute `name` of `object`.
void set_string_attribute(hid_t object, const char* name, std::string_view value, Where where);
void set_int64_attribute(hid_t object, const char* name, std::int64_t value, Where where);

}  // namespace mrsim::h5
