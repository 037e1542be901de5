#include "io/hdf5_read.hpp"

#include <sstream>

namespace mrsim::h5 {

namespace {

std::string dims_text(const std::vector<hsize_t>& dims) {
  std::ostringstream os;
  os << '[';
  for (size_t i = 0; i < dims.size(); ++i) os << (i ? ", " : "") << dims[i];
  os << ']';
  return os.str();
}

}  // namespace

bool has_link(hid_t parent, const std::string& name, Where where) {
  const htri_t exists = H5Lexists(parent, name.c_str(), H5P_DEFAULT);
  check(exists, where, "look up " + name);
  return exists > 0;
}

std::string read_string_attribute(hid_t object, const char* name, Where where) {
  const std::string what = std::string("read attribute ") + name;
  Handle attribute = checked(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, where, what);
  Handle file_type = checked(H5Aget_type(attribute.get()), H5Tclose, where, what);
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) <= 0)
    throw_error(where, what + " (not a variable-length string)");
  Handle type = utf8_string_type(where);
  char* value = nullptr;
  check(H5Aread(attribute.get(), type.get(), &value), where, what);
  std::string text = value ? value : "";
  H5free_memory(value);
  return text;
}

std::int64_t read_int64_attribute(hid_t object, const char* name, Where where) {
  const std::string what = std::string("read attribute ") + name;
  Handle attribute = checked(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, where, what);
  Handle file_type = checked(H5Aget_type(attribute.get()), H5Tclose, where, what);
  if (H5Tget_class(file_type.get()) != H5T_INTEGER) throw_error(where, what + " (not an integer)");
  std::int64_t value = 0;
  check(H5Aread(attribute.get(), TypeOf<std::int64_t>::memory(), &value), where, what);
  return value;
}

std::vector<hsize_t> dataset_dims(hid_t parent, const std::string& name, Where where) {
  Handle dataset =
      checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, where, "open dataset " + name);
  Handle space = checked(H5Dget_space(dataset.get()), H5Sclose, where, "get dataspace");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  check(rank, where, "read the rank of " + name);
  std::vector<hsize_t> dims(static_cast<size_t>(rank));
  check(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), where,
        "read the dimensions of " + name);
  return dims;
}

void read_dataset(hid_t parent, const std::string& name, hid_t memory_type, void* out,
                  const std::vector<hsize_t>& dims, Where where) {
  const std::vector<hsize_t> found = dataset_dims(parent, name, where);
  if (found != dims)
    throw_error(where, "read " + name + ": dimensions " + dims_text(found) + ", expected " +
                           dims_text(dims));
  Handle dataset =
      checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, where, "open dataset " + name);
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  if (n == 0) return;
  check(H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out), where,
        "read " + name);
}

}  // namespace mrsim::h5
