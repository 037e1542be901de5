#pragma once
// Scalar attributes on HDF5 objects: strings (variable-length UTF-8, read back as `str` by
// h5py) and integers.
#include <hdf5.h>

#include <cstdint>
#include <span>
#include <string_view>

#include "io/hdf5_error.hpp"

namespace mrsim::h5 {

/// Creates, or overwrites, attribute `name` of `object`.
void set_string_attribute(hid_t object, const char* name, std::string_view value, Where where);
void set_int64_attribute(hid_t object, const char* name, std::int64_t value, Where where);
/// A 1-D array of doubles (h5py reads a numpy float64 array).
void set_double_array_attribute(hid_t object, const char* name, std::span<const double> values,
                                Where where);
/// A 1-D array of UTF-8 strings (h5py reads a numpy array of str), e.g. column names.
void set_string_list_attribute(hid_t object, const char* name,
                               std::span<const char* const> values, Where where);

}  // namespace mrsim::h5
