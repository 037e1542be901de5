#include "io/hdf5_static_dataset.hpp"

#include "io/hdf5_attributes.hpp"
#include "io/hdf5_group.hpp"

namespace mrsim::h5 {

void write_static_dataset(hid_t parent, const std::string& name, hid_t file_type,
                          hid_t memory_type, const std::vector<hsize_t>& dims, const void* data,
                          const std::string& units, Where where) {
  Handle space = checked(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                         H5Sclose, where, "create dataspace");
  Handle properties = checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, where,
                              "create dataset properties");
  no_time_stamps(properties.get(), where);
  Handle dataset = checked(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                                      properties.get(), H5P_DEFAULT),
                           H5Dclose, where, "create dataset");
  hsize_t elements = 1;
  for (const hsize_t n : dims) elements *= n;
  if (elements > 0) {
    check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), where,
          "write dataset");
  }
  if (!units.empty()) set_string_attribute(dataset.get(), "units", units, where);
  check(dataset.close(), where, "close dataset");
}

}  // namespace mrsim::h5
