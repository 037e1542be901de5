#pragma once
// /frames in log.h5: one row per written frame (time, energies, wall time, per-level counters).
#include <hdf5.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "io/extendible_dataset.hpp"
#include "io/frame_data.hpp"

namespace mrsim::h5 {

class FrameTable {
 public:
  /// `time_level_steps`: the step (s) of each column of /frames/time_levels. With `tools`
  /// > 0, /frames/tool_force [F, tools, 3] exists too. Opens /frames when it exists (a log
  /// reopened to resume a run).
  FrameTable(hid_t file_id, std::size_t levels, const std::vector<double>& time_level_steps,
             std::size_t tools, const std::string& file);
  std::size_t time_levels() const { return time_levels_count_; }
  std::size_t tools() const { return tools_count_; }

  /// Appends one row to every dataset; /frames/frame goes last, so its length counts the
  /// frames whose every row was written (what a reader of a killed run should trust).
  void append(const FrameRecord& record);
  hsize_t rows() const { return frame_.rows(); }
  /// Keeps the first `rows` frames of every dataset.
  void truncate(hsize_t rows);
  void close();

 private:
  std::array<ExtendibleDataset*, 15> datasets();  // every one but tool_force_, frame_ last
  std::string file_;
  Handle group_;
  ExtendibleDataset time_, kinetic_energy_, elastic_energy_, wall_time_, stable_step_, step_;
  ExtendibleDataset wall_time_parts_;
  ExtendibleDataset active_, ghosts_, force_evaluations_, tet_updates_, support_reaction_;
  ExtendibleDataset time_levels_, time_level_evaluations_;
  std::size_t time_levels_count_ = 0;
  std::size_t tools_count_ = 0;
  std::optional<ExtendibleDataset> tool_force_;  // only with tools: the layout stays additive
  ExtendibleDataset frame_;
};

}  // namespace mrsim::h5
