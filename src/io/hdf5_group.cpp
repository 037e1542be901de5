#include "io/hdf5_group.hpp"

namespace mrsim::h5 {

void no_time_stamps(hid_t creation_properties, Where where) {
  check(H5Pset_obj_track_times(creation_properties, false), where, "disable time stamps");
}

Handle untimed_group_properties(Where where) {
  Handle properties = checked(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, where,
                              "create group properties");
  no_time_stamps(properties.get(), where);
  return properties;
}

Handle create_group(hid_t parent, const std::string& name, Where where) {
  Handle properties = untimed_group_properties(where);
  return checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                 H5Gclose, where, "create group");
}

Handle open_or_create_group(hid_t parent, const std::string& name, Where where, bool& created) {
  const htri_t exists = H5Lexists(parent, name.c_str(), H5P_DEFAULT);
  check(exists, where, "look up group");
  created = exists == 0;
  if (created) return create_group(parent, name, where);
  return checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, where, "open group");
}

}  // namespace mrsim::h5
