#pragma once
// The VTK series of two runs: frames.pvd's lists (count, times), then frame by frame (by
// position in the lists) every block by name: its type, point and cell counts, points, cells
// and arrays. Only one frame of each run is in memory at a time.
#include <filesystem>

#include "compare/compare_report.hpp"
#include "compare/tolerance.hpp"

namespace mrsim {

/// Adds to `report` (Section::Frames). A frames.pvd in one run only is a difference; in
/// neither, nothing is compared. Throws InputError naming the file when a frame or piece
/// cannot be read.
void diff_frames(const std::filesystem::path& run_a, const std::filesystem::path& run_b,
                 const Tolerance& tolerance, CompareReport& report);

}  // namespace mrsim
