#pragma once
// /tool (tool 0) and /tool_k (tool k >= 1) in log.h5: one rigid tool's samples, one row per
// simulation step (time, position, orientation, force, contacts), appended in batches of one
// frame's steps.
#include <hdf5.h>

#include <string>
#include <string_view>

#include "io/extendible_dataset.hpp"
#include "io/frame_data.hpp"

namespace mrsim::h5 {

/// The group name of tool `tool`: "tool" for the first, "tool_k" for the others.
std::string tool_group_name(int tool);

class ToolGroup {
 public:
  /// Creates the group of tool `tool` under the file's root, with attributes `name` and
  /// `shape` and five empty datasets; opens it when it exists (a log reopened to resume a run).
  ToolGroup(hid_t file_id, int tool, std::string_view name, std::string_view shape,
            const std::string& file);

  /// Appends every sample; `samples` must have passed check_tool_samples. `time` goes last,
  /// so its length counts the samples whose every column was written.
  void append(const ToolSamples& samples);
  hsize_t rows() const { return time_.rows(); }
  void truncate(hsize_t rows);
  void close();

 private:
  std::string path_;
  std::string file_;
  Handle group_;
  ExtendibleDataset time_, position_, orientation_, force_, contacts_;
};

}  // namespace mrsim::h5
