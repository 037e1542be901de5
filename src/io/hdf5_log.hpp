#pragma once
// log.h5 (product.md; layout documented in docs/output.md). Per-frame datasets are chunked and
// extendible, appended and flushed every frame so a killed run leaves a readable file.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/frame_data.hpp"

namespace mrsim {

struct Hdf5LogHeader {
  std::string version;        // mrsim version
  std::string git_revision;
  std::string scenario_yaml;  // the resolved scenario text
  std::string start_time;     // ISO 8601, UTC
  std::vector<const TetMesh*> levels;  // rest positions and tets stored under /levels/level_k
  // Step (s) of each column of /frames/time_levels: frame_dt / 2^k with time levels, else the
  // one step frame_dt / substeps. Stored as /frames/time_level_step. At least one.
  std::vector<double> time_level_steps;
};

class Hdf5Log {
 public:
  Hdf5Log(const std::filesystem::path& file, const Hdf5LogHeader& header);
  ~Hdf5Log();
  Hdf5Log(const Hdf5Log&) = delete;
  Hdf5Log& operator=(const Hdf5Log&) = delete;

  /// Appends one row to every /frames dataset and /levels/level_k/status, then flushes.
  void append_frame(const FrameRecord& record);
  /// Appends an event (split / merge / gc / time-level change / diagnostics) to /events.
  void append_event(int frame, const std::string& kind, int level, long long point);
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mrsim
