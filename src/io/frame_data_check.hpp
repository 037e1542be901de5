#pragma once
// Size checks of what the simulation hands to the writers. A mismatch is a programming error
// in the caller (not bad user input), so it throws std::invalid_argument with the array name.
#include <cstddef>
#include <span>

#include "io/frame_data.hpp"

namespace mrsim {

/// Every array of `view` has one value per point of `view.mesh` (which must be set).
void check_level_view(const LevelFrameView& view, int level);

/// Every per-vertex array of `surface` has one value per rest position, and every triangle
/// refers to existing vertices.
void check_surface_view(const SurfaceFrameView& surface);

/// Every triangle of tool `tool` refers to one of its points.
void check_tool_view(const ToolFrameView& view, int tool);

/// The five arrays of `samples` (of tool `tool`) have the same length.
void check_tool_samples(const ToolSamples& samples, int tool);

/// `record` has one entry per level in every per-level vector, `status[k]` has
/// `points_per_level[k]` values, every per-time-level vector has `time_levels` values and
/// `tool_force` has `tools` values (none without tools).
void check_frame_record(const FrameRecord& record, std::span<const std::size_t> points_per_level,
                        std::size_t time_levels, std::size_t tools);

}  // namespace mrsim
