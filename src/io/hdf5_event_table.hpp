#pragma once
// /events in log.h5: parallel datasets frame [E] i32, kind [E] string, level [E] i32,
// point [E] i64, one row per event. Events arrive one by one, often thousands per frame, so
// they are buffered and written in one batch per frame (write_pending) rather than one HDF5
// write per event.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/extendible_dataset.hpp"

namespace mrsim::h5 {

class EventTable {
 public:
  /// Creates /events, or opens it when it exists (a log reopened to resume a run).
  EventTable(hid_t file_id, const std::string& file);

  void add(int frame, const std::string& kind, int level, long long point);
  /// Writes the buffered events (if any) and empties the buffer.
  void write_pending();
  hsize_t rows() const { return frame_.rows(); }
  /// Keeps the first `rows` events (nothing may be pending).
  void truncate(hsize_t rows);
  void close();

 private:
  std::string file_;
  bool created_ = true;
  Handle group_;
  Handle string_type_;
  ExtendibleDataset frame_, kind_, level_, point_;
  std::vector<std::int32_t> pending_frame_;
  std::vector<std::string> pending_kind_;
  std::vector<std::int32_t> pending_level_;
  std::vector<std::int64_t> pending_point_;
};

}  // namespace mrsim::h5
