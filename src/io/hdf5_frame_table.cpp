#include "io/hdf5_frame_table.hpp"

#include <cstdint>
#include <span>
#include <vector>

#include "io/hdf5_attributes.hpp"
#include "io/hdf5_group.hpp"
#include "io/hdf5_static_dataset.hpp"

namespace mrsim::h5 {
namespace {

constexpr hsize_t kScalarChunkRows = 128;

template <class T>
ExtendibleSpec scalar_spec(const char* name, const char* units, const char* description) {
  ExtendibleSpec spec;
  spec.name = name;
  spec.file_type = TypeOf<T>::file();
  spec.chunk_rows = kScalarChunkRows;
  spec.units = units;
  spec.description = description;
  return spec;
}

ExtendibleSpec per_level_spec(const char* name, std::size_t levels, const char* description) {
  ExtendibleSpec spec;
  spec.name = name;
  spec.file_type = TypeOf<std::int64_t>::file();
  spec.row_shape = {levels};
  spec.chunk_rows = chunk_rows_for(levels * sizeof(std::int64_t), kScalarChunkRows);
  spec.description = description;
  return spec;
}

ExtendibleSpec vector_spec(const char* name, const char* units, const char* description) {
  ExtendibleSpec spec = scalar_spec<double>(name, units, description);
  spec.row_shape = {3};
  spec.chunk_rows = chunk_rows_for(3 * sizeof(double), kScalarChunkRows);
  return spec;
}

ExtendibleSpec tool_force_spec(std::size_t tools) {
  ExtendibleSpec spec = scalar_spec<double>(
      "tool_force", "N", "force the object exerts on each tool at the end of the frame");
  spec.row_shape = {tools, 3};
  spec.chunk_rows = chunk_rows_for(tools * 3 * sizeof(double), kScalarChunkRows);
  return spec;
}

// Row-major [T, 3]: one contiguous row for HDF5, without relying on Eigen's array layout.
std::vector<double> flatten(const std::vector<Vec3>& vectors) {
  std::vector<double> values;
  values.reserve(3 * vectors.size());
  for (const Vec3& v : vectors) values.insert(values.end(), {v.x(), v.y(), v.z()});
  return values;
}

template <class T>
void append_one(ExtendibleDataset& dataset, const T& value) {
  dataset.append(std::span<const T>(&value, 1));
}

}  // namespace

FrameTable::FrameTable(hid_t file_id, std::size_t levels,
                       const std::vector<double>& time_level_steps, std::size_t tools,
                       const std::string& file)
    : file_(file), time_levels_count_(time_level_steps.size()), tools_count_(tools) {
  bool created = true;
  group_ = open_or_create_group(file_id, "frames", {file_, "/frames"}, created);
  const hid_t g = group_.get();
  const auto mode = created ? ExtendibleDataset::Mode::Create : ExtendibleDataset::Mode::Reopen;
  if (created)
    write_static_dataset(g, "time_level_step", std::span<const double>(time_level_steps),
                         {time_level_steps.size()}, "s", {file_, "/frames/time_level_step"});
  time_levels_ = {g, "/frames",
                  per_level_spec("time_levels", time_levels_count_,
                                 "integrated particles per time level at the end of the frame; "
                                 "column k steps time_level_step[k]"),
                  file_, mode};
  time_level_evaluations_ = {g, "/frames",
                             per_level_spec("time_level_evaluations", time_levels_count_,
                                            "cumulative point-force evaluations per time level"),
                             file_, mode};
  time_ = {g, "/frames", scalar_spec<double>("time", "s", "simulated time of the frame"), file_, mode};
  kinetic_energy_ = {g, "/frames",
                     scalar_spec<double>("kinetic_energy", "J", "sum of m v^2 / 2"), file_, mode};
  elastic_energy_ = {g, "/frames",
                     scalar_spec<double>("elastic_energy", "J", "strain energy"), file_, mode};
  wall_time_ = {g, "/frames",
                scalar_spec<double>("wall_time", "s", "wall clock spent simulating this frame"),
                file_, mode};
  ExtendibleSpec parts = scalar_spec<double>(
      "wall_time_parts", "s",
      "wall clock of the frame per task (column names in attribute `names`; they sum to the "
      "frame's whole wall time, output included; docs/output.md)");
  parts.row_shape = {kTaskCount};
  parts.chunk_rows = chunk_rows_for(kTaskCount * sizeof(double), kScalarChunkRows);
  wall_time_parts_ = {g, "/frames", parts, file_, mode};
  if (created)
    set_string_list_attribute(wall_time_parts_.id(), "names", kTaskNames,
                              {file_, "/frames/wall_time_parts"});
  stable_step_ = {g, "/frames",
                  scalar_spec<double>("stable_step", "s",
                                      "smallest stable step estimate of the active points at the "
                                      "end of the frame (docs/integrators.md)"),
                  file_, mode};
  step_ = {g, "/frames",
           scalar_spec<double>("step", "s", "finest step the frame took (frame_dt / substeps, or "
                                            "the finest time level)"),
           file_, mode};
  active_ = {g, "/frames", per_level_spec("active", levels, "active points per level"), file_, mode};
  ghosts_ = {g, "/frames", per_level_spec("ghosts", levels, "ghost points per level"), file_, mode};
  force_evaluations_ = {g, "/frames",
                        per_level_spec("force_evaluations", levels,
                                       "cumulative point-force evaluations per level"),
                        file_, mode};
  tet_updates_ = {g, "/frames",
                  per_level_spec("tet_updates", levels,
                                 "cumulative per-tet stress evaluations per level (Green-Lagrange "
                                 "and weighted tet passes; docs/output.md)"),
                  file_, mode};
  support_reaction_ = {g, "/frames",
                       vector_spec("support_reaction", "N",
                                   "force the fixed points exert on the body, at the last force "
                                   "evaluation of the frame"),
                       file_, mode};
  if (tools > 0) tool_force_.emplace(g, "/frames", tool_force_spec(tools), file_, mode);
  frame_ = {g, "/frames",
            scalar_spec<std::int32_t>("frame", "", "frame index (frame_NNNNNN.vtm)"), file_, mode};
}

void FrameTable::append(const FrameRecord& record) {
  append_one(time_, record.time);
  append_one(kinetic_energy_, record.kinetic_energy);
  append_one(elastic_energy_, record.elastic_energy);
  append_one(wall_time_, record.wall_time);
  wall_time_parts_.append(std::span<const double>(record.wall_time_parts));
  append_one(stable_step_, record.stable_step);
  append_one(step_, record.step);
  active_.append(std::span<const std::int64_t>(record.active));
  ghosts_.append(std::span<const std::int64_t>(record.ghosts));
  force_evaluations_.append(std::span<const std::int64_t>(record.force_evaluations));
  tet_updates_.append(std::span<const std::int64_t>(record.tet_updates));
  time_levels_.append(std::span<const std::int64_t>(record.time_levels));
  time_level_evaluations_.append(std::span<const std::int64_t>(record.time_level_evaluations));
  support_reaction_.append(std::span<const double>(record.support_reaction.data(), 3));
  if (tool_force_) tool_force_->append(std::span<const double>(flatten(record.tool_force)));
  append_one(frame_, static_cast<std::int32_t>(record.frame));
}

std::array<ExtendibleDataset*, 15> FrameTable::datasets() {
  return {&time_,   &kinetic_energy_,   &elastic_energy_,   &wall_time_,        &wall_time_parts_,
          &stable_step_, &step_,         &active_,           &ghosts_,           &force_evaluations_,
          &tet_updates_, &support_reaction_, &time_levels_, &time_level_evaluations_, &frame_};
}

void FrameTable::truncate(hsize_t rows) {
  for (ExtendibleDataset* d : datasets()) d->truncate(rows);
  if (tool_force_) tool_force_->truncate(rows);
}

void FrameTable::close() {
  for (ExtendibleDataset* d : datasets()) d->close();
  if (tool_force_) tool_force_->close();
  check(group_.close(), {file_, "/frames"}, "close group");
}

}  // namespace mrsim::h5
