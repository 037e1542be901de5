#pragma once
// OUTDIR/checkpoint.h5 (docs/output.md "Checkpoints and --resume"): a Checkpoint in HDF5,
// versioned (root attributes `format` = "mrsim checkpoint", `format_version`), written to a
// temporary file, synced and renamed over the previous one, so a run killed at any instant
// leaves either the previous checkpoint or the new one, whole.
#include <filesystem>

#include "io/checkpoint_data.hpp"

namespace mrsim {

inline constexpr const char* kCheckpointFile = "checkpoint.h5";

/// Writes `checkpoint` to `file` atomically, with the bytes of the run's `log` (flushed at the
/// same frame) inside it as `/log_h5`. Throws RunError (disk full, folder removed).
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& checkpoint,
                      const std::filesystem::path& log);

/// Reads a checkpoint back, every array checked against the level sizes it declares. Throws
/// InputError naming the file when it is missing, not a checkpoint, of another format version,
/// or damaged. Whether it fits the scenario and this build is the caller's decision.
Checkpoint read_checkpoint(const std::filesystem::path& file);

/// Replaces `log` (atomically) by the copy of it that checkpoint `file` holds: the log exactly
/// as it was at the checkpoint's frame, whatever a run killed later did to it. Throws
/// InputError when the checkpoint is damaged, RunError when `log` cannot be written.
void restore_checkpoint_log(const std::filesystem::path& file, const std::filesystem::path& log);

}  // namespace mrsim
