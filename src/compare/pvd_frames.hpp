#pragma once
// The frame list of a run: frames.pvd's entries, each a simulated time and its .vtm.
#include <filesystem>
#include <vector>

namespace mrsim {

struct PvdFrame {
  double time = 0;             // s, the `timestep` attribute
  std::filesystem::path file;  // the .vtm, resolved against the .pvd's folder
};

/// Throws InputError naming `pvd` when it cannot be read or an entry lacks a valid
/// `timestep` or `file`.
std::vector<PvdFrame> read_pvd_frames(const std::filesystem::path& pvd);

/// The frame index in a file name "frame_000012.vtm" (12); `fallback` when there is none.
long long frame_number(const std::filesystem::path& vtm, long long fallback);

}  // namespace mrsim
