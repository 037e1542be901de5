#pragma once
// The HDF5 types mrsim stores, per C++ element type: `file` is the fixed little-endian type on
// disk (identical files on every machine), `memory` the native type HDF5 converts from.
#include <hdf5.h>

#include <cstdint>

#include "io/hdf5_error.hpp"

namespace mrsim::h5 {

template <class T>
struct TypeOf;

template <>
struct TypeOf<double> {
  static hid_t file() { return H5T_IEEE_F64LE; }
  static hid_t memory() { return H5T_NATIVE_DOUBLE; }
};
template <>
struct TypeOf<std::int8_t> {
  static hid_t file() { return H5T_STD_I8LE; }
  static hid_t memory() { return H5T_NATIVE_INT8; }
};
template <>
struct TypeOf<std::int32_t> {
  static hid_t file() { return H5T_STD_I32LE; }
  static hid_t memory() { return H5T_NATIVE_INT32; }
};
template <>
struct TypeOf<std::int64_t> {
  static hid_t file() { return H5T_STD_I64LE; }
  static hid_t memory() { return H5T_NATIVE_INT64; }
};

/// Variable-length UTF-8 string type (same in memory and on disk; values are `const char*`).
Handle utf8_string_type(Where where);

}  // namespace mrsim::h5
