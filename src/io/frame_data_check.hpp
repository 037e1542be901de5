#pragma once
// Size checks of what the simulation hands to the writers. A mismatch is a programming error
// in the caller (not bad user input), so it throws std::invalid_argument with the array name.
#include <cstddef>
#include <span>

#include "io/frame_data.hpp"

namespace mrsim {

/// Every array of `view` has one value per point of `view.mesh` (which must be set).
void check_level_view(const LevelFrameView& view, int level);

/// `record` has one entry per level in every per-level vector, and `status[k]` has
/// `points_per_level[k]` values.
/// and `time_levels` values per time-level vector.
void check_frame_record(const FrameRecord& record, std::span<const std::size_t> points_per_level,
                        std::size_t time_levels);

}  // namespace mrsim
