#pragma once
// log.h5 (product.md; layout documented in docs/output.md). Per-frame datasets are chunked and
// extendible, appended and flushed every frame so a killed run leaves a readable file.
#include <filesystem>
#include <memory>
#include <cstdint>
#include <string>
#include <vector>

#include "io/frame_data.hpp"

namespace mrsim {

/// One tool as named in the scenario, stored as the attributes of its group in log.h5.
struct ToolLogInfo {
  std::string name;   // scenario `tools[].name`
  std::string shape;  // sphere, capsule, flat_cylinder, ...
};

struct NamedValues {
  std::string name;
  std::vector<double> values;
};

struct Hdf5LogHeader {
  std::string version;        // mrsim version
  std::string git_revision;
  std::string scenario_yaml;  // the resolved scenario text
  std::string start_time;     // ISO 8601, UTC
  std::vector<const TetMesh*> levels;  // rest positions and tets stored under /levels/level_k
  // Step (s) of each column of /frames/time_levels: frame_dt / 2^k with time levels, else the
  // one step frame_dt / substeps. Stored as /frames/time_level_step. At least one.
  std::vector<double> time_level_steps;
  // One entry per tool, in the simulation's tool order: tool 0 is logged under /tool, tool k
  // under /tool_k, and every FrameRecord then carries one tool_force per tool. Empty: no tool
  // objects at all. (Defaulted so that brace-initialised headers need not list it.)
  std::vector<ToolLogInfo> tools = {};
  // Per level, float64 array attributes of /levels/level_k (a calibrated level's scales and fit
  // ratios); written when the log is created.
  std::vector<std::vector<NamedValues>> level_attributes = {};
};

/// How many rows of each table of an existing log belong to the frames a resumed run keeps.
struct Hdf5LogRows {
  std::int64_t frames = 0;  // rows of /frames/* and /levels/level_k/status
  std::int64_t events = 0;  // rows of /events/*
  std::vector<std::int64_t> tool_samples;  // rows of /tool, /tool_k
};

class Hdf5Log {
 public:
  Hdf5Log(const std::filesystem::path& file, const Hdf5LogHeader& header);
  /// Reopens the log of a run to go on with it (mrsim run --resume): the header must describe
  /// the same levels, time levels and tools; every table is cut to `keep` rows (what a run
  /// killed after its checkpoint wrote beyond is dropped); the header attributes, start_time
  /// included, stay those of the run's start. Throws RunError when the file is not such a log
  /// or holds fewer rows.
  Hdf5Log(const std::filesystem::path& file, const Hdf5LogHeader& header, const Hdf5LogRows& keep);
  ~Hdf5Log();
  Hdf5Log(const Hdf5Log&) = delete;
  Hdf5Log& operator=(const Hdf5Log&) = delete;

  /// Appends one row to every /frames dataset and /levels/level_k/status, then flushes.
  void append_frame(const FrameRecord& record);
  /// Appends an event (split / merge / gc / time-level change / diagnostics) to /events.
  void append_event(int frame, const std::string& kind, int level, long long point);
  /// Appends the samples of tool `tool` (an index into Hdf5LogHeader::tools) to its group.
  /// Empty samples append nothing; spans of different lengths or a tool index out of range
  /// throw std::invalid_argument. Written at once, made durable by the next append_frame's
  /// flush.
  void append_tool_samples(int tool, const ToolSamples& samples);
  /// Rows written so far (events still buffered excluded): what a checkpoint records.
  Hdf5LogRows rows() const;
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mrsim
