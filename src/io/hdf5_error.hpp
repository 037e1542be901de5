#pragma once
// HDF5 failures become RunError naming the file, the object and what was attempted, with
// HDF5's own diagnosis appended. HDF5's default habit of printing its error stack to stderr is
// switched off: mrsim reports errors itself, once, through the exception.
#include <hdf5.h>

#include <string_view>

#include "io/hdf5_handle.hpp"

namespace mrsim::h5 {

/// Where an HDF5 call acts, for messages: "out/log.h5", "/frames/time".
struct Where {
  std::string_view file;
  std::string_view object;
};

/// Turns off automatic error-stack printing (process-wide, done once).
void silence_automatic_error_printing();

[[noreturn]] void throw_error(Where where, std::string_view action);

/// Throws unless `status` is non-negative (HDF5's success convention).
inline void check(herr_t status, Where where, std::string_view action) {
  if (status < 0) throw_error(where, action);
}

/// Wraps a freshly returned id, throwing if HDF5 returned a failure instead.
inline Handle checked(hid_t id, CloseFunction close_function, Where where,
                      std::string_view action) {
  if (id < 0) throw_error(where, action);
  return Handle(id, close_function);
}

}  // namespace mrsim::h5
