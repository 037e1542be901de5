#pragma once
// A run's frames as a time series (io/vtk_series_writer.hpp writes it for ParaView). The
// interface through which the run calls the writer VTK's library provides (core/vtk_module.hpp):
// one virtual call per frame.
#include <span>
#include <utility>

#include "io/frame_data.hpp"

namespace mrsim {

class FrameSeriesWriter {
 public:
  virtual ~FrameSeriesWriter() = default;
  /// VtkSeriesWriter::write_frame.
  virtual void write_frame(int frame_index, double time, std::span<const LevelFrameView> levels,
                           const SurfaceFrameView* surface = nullptr,
                           std::span<const ToolFrameView> tools = {}) = 0;
  /// VtkSeriesWriter::resume.
  virtual void resume(std::span<const std::pair<int, double>> kept, int last) = 0;
};

}  // namespace mrsim
