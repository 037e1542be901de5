#pragma once
// Owns one HDF5 identifier and closes it with the matching H5?close function, so that no id
// leaks on any path, exceptions included. Internal to mrsim_io: hdf5.h stays out of the
// public headers.
#include <hdf5.h>

#include <utility>

namespace mrsim::h5 {

using CloseFunction = herr_t (*)(hid_t);

class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, CloseFunction close_function) noexcept : id_(id), close_(close_function) {}
  ~Handle() { (void)close(); }
  Handle(Handle&& other) noexcept
      : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      (void)close();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      close_ = other.close_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const noexcept { return id_; }
  bool valid() const noexcept { return id_ >= 0; }

  /// Closes now; returns HDF5's status so that callers who must know (the file) can check it.
  herr_t close() noexcept {
    herr_t status = 0;
    if (id_ >= 0 && close_ != nullptr) status = close_(id_);
    id_ = H5I_INVALID_HID;
    return status;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  CloseFunction close_ = nullptr;
};

}  // namespace mrsim::h5
