#include "io/hdf5_attributes.hpp"

#include <string>

#include "io/hdf5_types.hpp"

namespace mrsim::h5 {
namespace {

// Creates attribute `name` with `type` and `space`, replacing it when it exists (values such
// as counters are rewritten).
Handle new_attribute(hid_t object, const char* name, hid_t type, hid_t space, Where where) {
  const htri_t exists = H5Aexists(object, name);
  check(exists, where, std::string("look up attribute ") + name);
  if (exists > 0) {
    check(H5Adelete(object, name), where, std::string("replace attribute ") + name);
  }
  return checked(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, where,
                 std::string("create attribute ") + name);
}

Handle scalar_attribute(hid_t object, const char* name, hid_t type, Where where) {
  Handle space = checked(H5Screate(H5S_SCALAR), H5Sclose, where, "create scalar dataspace");
  return new_attribute(object, name, type, space.get(), where);
}

}  // namespace

void set_string_attribute(hid_t object, const char* name, std::string_view value, Where where) {
  Handle type = utf8_string_type(where);
  Handle attribute = scalar_attribute(object, name, type.get(), where);
  const std::string text(value);  // NUL-terminated copy
  const char* pointer = text.c_str();
  check(H5Awrite(attribute.get(), type.get(), &pointer), where,
        std::string("write attribute ") + name);
  check(attribute.close(), where, std::string("close attribute ") + name);
}

void set_int64_attribute(hid_t object, const char* name, std::int64_t value, Where where) {
  Handle attribute = scalar_attribute(object, name, TypeOf<std::int64_t>::file(), where);
  check(H5Awrite(attribute.get(), TypeOf<std::int64_t>::memory(), &value), where,
        std::string("write attribute ") + name);
  check(attribute.close(), where, std::string("close attribute ") + name);
}

void set_double_array_attribute(hid_t object, const char* name, std::span<const double> values,
                                Where where) {
  const hsize_t n = values.size();
  Handle space = checked(H5Screate_simple(1, &n, nullptr), H5Sclose, where, "create dataspace");
  Handle attribute = new_attribute(object, name, H5T_IEEE_F64LE, space.get(), where);
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, values.data()), where,
        std::string("write attribute ") + name);
  check(attribute.close(), where, std::string("close attribute ") + name);
}

void set_string_list_attribute(hid_t object, const char* name,
                               std::span<const char* const> values, Where where) {
  Handle type = utf8_string_type(where);
  const hsize_t n = values.size();
  Handle space = checked(H5Screate_simple(1, &n, nullptr), H5Sclose, where, "create dataspace");
  Handle attribute = new_attribute(object, name, type.get(), space.get(), where);
  check(H5Awrite(attribute.get(), type.get(), values.data()), where,
        std::string("write attribute ") + name);
  check(attribute.close(), where, std::string("close attribute ") + name);
}

}  // namespace mrsim::h5
