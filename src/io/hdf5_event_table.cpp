#include "io/hdf5_event_table.hpp"

#include <span>

#include "io/hdf5_group.hpp"

namespace mrsim::h5 {
namespace {

constexpr hsize_t kEventChunkRows = 256;

ExtendibleSpec event_spec(const char* name, hid_t file_type, const char* description) {
  ExtendibleSpec spec;
  spec.name = name;
  spec.file_type = file_type;
  spec.chunk_rows = kEventChunkRows;
  spec.description = description;
  return spec;
}

}  // namespace

EventTable::EventTable(hid_t file_id, const std::string& file)
    : file_(file),
      group_(open_or_create_group(file_id, "events", {file_, "/events"}, created_)),
      string_type_(utf8_string_type({file_, "/events"})) {
  const hid_t g = group_.get();
  const auto mode = created_ ? ExtendibleDataset::Mode::Create : ExtendibleDataset::Mode::Reopen;
  frame_ = {g, "/events",
            event_spec("frame", TypeOf<std::int32_t>::file(), "frame during which it happened"),
            file_, mode};
  kind_ = {g, "/events",
           event_spec("kind", string_type_.get(),
                      "split, merge, gc, time_level or a diagnostic name"),
           file_, mode};
  level_ = {g, "/events", event_spec("level", TypeOf<std::int32_t>::file(), "level index"),
            file_, mode};
  point_ = {g, "/events",
            event_spec("point", TypeOf<std::int64_t>::file(), "point index in its level, -1 if none"),
            file_, mode};
}

void EventTable::add(int frame, const std::string& kind, int level, long long point) {
  pending_frame_.push_back(frame);
  pending_kind_.push_back(kind);
  pending_level_.push_back(level);
  pending_point_.push_back(point);
}

void EventTable::write_pending() {
  if (pending_frame_.empty()) return;
  frame_.append(std::span<const std::int32_t>(pending_frame_));
  std::vector<const char*> kinds;
  kinds.reserve(pending_kind_.size());
  for (const std::string& k : pending_kind_) kinds.push_back(k.c_str());
  kind_.append(kinds.data(), string_type_.get(), kinds.size());
  level_.append(std::span<const std::int32_t>(pending_level_));
  point_.append(std::span<const std::int64_t>(pending_point_));
  // clear() keeps the capacity: no allocation per frame once the buffers have grown.
  pending_frame_.clear();
  pending_kind_.clear();
  pending_level_.clear();
  pending_point_.clear();
}

void EventTable::truncate(hsize_t rows) {
  for (ExtendibleDataset* d : {&frame_, &kind_, &level_, &point_}) d->truncate(rows);
}

void EventTable::close() {
  write_pending();
  for (ExtendibleDataset* d : {&frame_, &kind_, &level_, &point_}) d->close();
  check(string_type_.close(), {file_, "/events"}, "close string type");
  check(group_.close(), {file_, "/events"}, "close group");
}

}  // namespace mrsim::h5
