#pragma once
// Group creation for log.h5. Object modification times are not recorded (here and on every
// dataset) so that two identical runs write identical objects.
#include <hdf5.h>

#include <string>

#include "io/hdf5_error.hpp"

namespace mrsim::h5 {

Handle create_group(hid_t parent, const std::string& name, Where where);
/// Opens group `name` when it exists (a log reopened to resume a run), creates it otherwise;
/// `created` says which.
Handle open_or_create_group(hid_t parent, const std::string& name, Where where, bool& created);

/// Group creation properties without time stamps (datasets use the same idea in their own
/// creation properties, see no_time_stamps).
Handle untimed_group_properties(Where where);

/// Turns off time stamps in a dataset or group creation property list.
void no_time_stamps(hid_t creation_properties, Where where);

}  // namespace mrsim::h5
