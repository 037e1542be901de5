#pragma once
// /levels/level_k in log.h5: the rest geometry of one level (written once) and its per-frame
// point status (one row appended per frame).
#include <hdf5.h>

#include <cstdint>
#include <span>
#include <string>

#include "io/extendible_dataset.hpp"
#include "mesh/tet_mesh.hpp"

namespace mrsim::h5 {

class LevelGroup {
 public:
  /// Creates level_`level` under the /levels group and writes rest_positions and tets; opens
  /// it when it exists (a log reopened to resume a run).
  LevelGroup(hid_t levels_group, int level, const TetMesh& mesh, const std::string& file);

  std::size_t points() const { return points_; }
  /// A 1-D float64 attribute of the group (the level's calibration, docs/output.md).
  void set_attribute(const std::string& name, std::span<const double> values);
  void append_status(std::span<const std::int8_t> status) { status_.append(status); }
  void truncate(hsize_t frames) { status_.truncate(frames); }
  hsize_t rows() const { return status_.rows(); }
  void close();

 private:
  std::string path_;
  std::string file_;
  std::size_t points_ = 0;
  Handle group_;
  ExtendibleDataset status_;
};

}  // namespace mrsim::h5
