#pragma once
// /frames in log.h5: one row per written frame (time, energies, wall time, per-level counters).
#include <hdf5.h>

#include <string>
#include <vector>

#include "io/extendible_dataset.hpp"
#include "io/frame_data.hpp"

namespace mrsim::h5 {

class FrameTable {
 public:
  /// `time_level_steps`: the step (s) of each column of /frames/time_levels.
  FrameTable(hid_t file_id, std::size_t levels, const std::vector<double>& time_level_steps,
             const std::string& file);
  std::size_t time_levels() const { return time_levels_count_; }

  /// Appends one row to every dataset; /frames/frame goes last, so its length counts the
  /// frames whose every row was written (what a reader of a killed run should trust).
  void append(const FrameRecord& record);
  hsize_t rows() const { return frame_.rows(); }
  void close();

 private:
  std::string file_;
  Handle group_;
  ExtendibleDataset time_, kinetic_energy_, elastic_energy_, wall_time_;
  ExtendibleDataset active_, ghosts_, force_evaluations_, support_reaction_;
  ExtendibleDataset time_levels_, time_level_evaluations_;
  std::size_t time_levels_count_ = 0;
  ExtendibleDataset frame_;
};

}  // namespace mrsim::h5
