#include "io/hdf5_types.hpp"

namespace mrsim::h5 {

Handle utf8_string_type(Where where) {
  Handle type = checked(H5Tcopy(H5T_C_S1), H5Tclose, where, "create string type");
  check(H5Tset_size(type.get(), H5T_VARIABLE), where, "make string type variable-length");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), where, "make string type UTF-8");
  return type;
}

}  // namespace mrsim::h5
