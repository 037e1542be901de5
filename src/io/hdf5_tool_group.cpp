#include "io/hdf5_tool_group.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "io/hdf5_attributes.hpp"
#include "io/hdf5_group.hpp"

namespace mrsim::h5 {
namespace {

// One row per simulation step: more rows per frame than /frames, hence more rows per chunk
// (still about 4 KiB, chunk_rows_for: each frame's flush rewrites the last chunk).
constexpr hsize_t kSampleChunkRows = 512;

template <class T>
ExtendibleSpec sample_spec(const char* name, hsize_t columns, const char* units,
                           const char* description) {
  ExtendibleSpec spec;
  spec.name = name;
  spec.file_type = TypeOf<T>::file();
  if (columns > 1) spec.row_shape = {columns};
  spec.chunk_rows = chunk_rows_for(columns * sizeof(T), kSampleChunkRows);
  spec.units = units;
  spec.description = description;
  return spec;
}

// Row-major doubles of fixed-size rows (Vec3, quaternion): HDF5 wants one contiguous buffer,
// and copying avoids relying on how Eigen lays out an array of vectors.
template <class Row, std::size_t N>
std::vector<double> flatten(std::span<const Row> rows) {
  std::vector<double> values;
  values.reserve(N * rows.size());
  for (const Row& row : rows) {
    for (std::size_t c = 0; c < N; ++c) values.push_back(row[static_cast<int>(c)]);
  }
  return values;
}

}  // namespace

std::string tool_group_name(int tool) {
  return tool == 0 ? "tool" : "tool_" + std::to_string(tool);
}

ToolGroup::ToolGroup(hid_t file_id, int tool, std::string_view name, std::string_view shape,
                     const std::string& file)
    : file_(file) {
  const std::string group_name = tool_group_name(tool);
  path_ = "/" + group_name;
  bool created = true;
  group_ = open_or_create_group(file_id, group_name, {file_, path_}, created);
  if (created) {
    set_string_attribute(group_.get(), "name", name, {file_, path_});
    set_string_attribute(group_.get(), "shape", shape, {file_, path_});
  }
  const hid_t g = group_.get();
  const auto mode = created ? ExtendibleDataset::Mode::Create : ExtendibleDataset::Mode::Reopen;
  time_ = {g, path_, sample_spec<double>("time", 1, "s", "simulated time of the step"), file_, mode};
  position_ = {g, path_,
               sample_spec<double>("position", 3, "m", "tool origin in the world frame"), file_, mode};
  orientation_ = {g, path_,
                  sample_spec<double>("orientation", 4, "",
                                      "unit quaternion w, x, y, z: tool frame to world frame"),
                  file_, mode};
  force_ = {g, path_,
            sample_spec<double>("force", 3, "N", "force the object exerts on the tool"), file_, mode};
  contacts_ = {g, path_,
               sample_spec<std::int32_t>("contacts", 1, "", "skin vertices in contact"), file_, mode};
}

void ToolGroup::append(const ToolSamples& samples) {
  position_.append(std::span<const double>(flatten<Vec3, 3>(samples.position)));
  orientation_.append(
      std::span<const double>(flatten<std::array<double, 4>, 4>(samples.orientation)));
  force_.append(std::span<const double>(flatten<Vec3, 3>(samples.force)));
  contacts_.append(samples.contacts);
  time_.append(samples.time);
}

void ToolGroup::truncate(hsize_t rows) {
  for (ExtendibleDataset* d : {&time_, &position_, &orientation_, &force_, &contacts_})
    d->truncate(rows);
}

void ToolGroup::close() {
  for (ExtendibleDataset* d : {&time_, &position_, &orientation_, &force_, &contacts_}) {
    d->close();
  }
  check(group_.close(), {file_, path_}, "close group");
}

}  // namespace mrsim::h5
