#pragma once
// Test-side reading of log.h5 with the plain HDF5 C API, independent of the writer's helpers,
// so the tests check the file a user gets rather than mrsim's view of it.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrsim::test {

/// Closes an HDF5 id at scope exit (H5Oclose/H5Sclose/... chosen by the caller).
class H5Id {
 public:
  H5Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error("HDF5 call failed");
  }
  ~H5Id() { close_(id_); }
  H5Id(const H5Id&) = delete;
  H5Id& operator=(const H5Id&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// Opens read-only. Without locking, a file still held open by a live writer can be read.
inline hid_t open_read_only(const std::filesystem::path& file, bool file_locking = true) {
  H5Id access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!file_locking) H5Pset_file_locking(access, false, true);
  return H5Fopen(file.c_str(), H5F_ACC_RDONLY, access);
}

template <class T>
hid_t native_type();
template <>
inline hid_t native_type<double>() { return H5T_NATIVE_DOUBLE; }
template <>
inline hid_t native_type<std::int8_t>() { return H5T_NATIVE_INT8; }
template <>
inline hid_t native_type<std::int32_t>() { return H5T_NATIVE_INT32; }
template <>
inline hid_t native_type<std::int64_t>() { return H5T_NATIVE_INT64; }

inline std::vector<hsize_t> dims_of(hid_t dataset, std::vector<hsize_t>* max_dims = nullptr) {
  H5Id space(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank)), max(dims.size());
  H5Sget_simple_extent_dims(space, dims.data(), max.data());
  if (max_dims != nullptr) *max_dims = max;
  return dims;
}

/// Bytes of one chunk of a chunked dataset (its element size times its chunk's extent).
inline hsize_t chunk_bytes(hid_t dataset, const std::vector<hsize_t>& chunk) {
  H5Id type(H5Dget_type(dataset), H5Tclose);
  hsize_t bytes = H5Tget_size(type);
  for (const hsize_t c : chunk) bytes *= c;
  return bytes;
}

template <class T>
struct Array {
  std::vector<hsize_t> dims;
  std::vector<T> values;
};

template <class T>
Array<T> read_array(hid_t file, const char* path) {
  H5Id dataset(H5Dopen2(file, path, H5P_DEFAULT), H5Dclose);
  Array<T> out;
  out.dims = dims_of(dataset);
  hsize_t count = 1;
  for (const hsize_t n : out.dims) count *= n;
  out.values.resize(count);
  if (count > 0 &&
      H5Dread(dataset, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data()) < 0) {
    throw std::runtime_error(std::string("cannot read ") + path);
  }
  return out;
}

inline std::vector<std::string> read_strings(hid_t file, const char* path) {
  H5Id dataset(H5Dopen2(file, path, H5P_DEFAULT), H5Dclose);
  H5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  H5Id space(H5Dget_space(dataset), H5Sclose);
  std::vector<char*> raw(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  if (!raw.empty()) H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data());
  std::vector<std::string> out(raw.begin(), raw.end());
  if (!raw.empty()) H5Dvlen_reclaim(type, space, H5P_DEFAULT, raw.data());
  return out;
}

inline std::string read_string_attribute(hid_t object, const char* name) {
  H5Id attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  H5Id stored(H5Aget_type(attribute), H5Tclose);
  if (H5Tis_variable_str(stored) <= 0) throw std::runtime_error("not a variable-length string");
  H5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  char* raw = nullptr;
  H5Aread(attribute, type, &raw);
  std::string value = raw != nullptr ? raw : "";
  H5free_memory(raw);
  return value;
}

inline std::int64_t read_int_attribute(hid_t object, const char* name) {
  H5Id attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  std::int64_t value = 0;
  H5Aread(attribute, H5T_NATIVE_INT64, &value);
  return value;
}

/// True when the dataset's type on disk is exactly `file_type` (e.g. H5T_STD_I8LE).
inline bool stored_as(hid_t file, const char* path, hid_t file_type) {
  H5Id dataset(H5Dopen2(file, path, H5P_DEFAULT), H5Dclose);
  H5Id type(H5Dget_type(dataset), H5Tclose);
  return H5Tequal(type, file_type) > 0;
}

}  // namespace mrsim::test
