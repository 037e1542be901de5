#pragma once
// Replaces a small text file so that a reader, or a run killed at any instant, sees either the
// old or the new content, never a torn one: write a sibling temporary file, then rename it
// over the target (rename is atomic within one file system on POSIX).
#include <filesystem>
#include <functional>
#include <string_view>

namespace mrsim {

/// Whether the temporary's bytes are fsynced before the rename publishes them: for files a run
/// goes on from (checkpoint.h5 and the log it restores); not for the per-frame small files.
enum class Durability { Renamed, Synced };

/// Replaces `file` atomically: `write` makes the sibling `file`.tmp (given as its argument),
/// which is then synced (Durability::Synced) and renamed over `file`. On any failure the
/// temporary is removed, `file` is left as it was and the error propagates (RunError naming
/// the file for the sync and the rename).
void replace_atomically(const std::filesystem::path& file,
                        const std::function<void(const std::filesystem::path& tmp)>& write,
                        Durability durability = Durability::Renamed);

/// Writes `contents` to `file` atomically. Throws RunError naming the file on failure; the
/// temporary file is removed and `file` is left untouched in that case.
void write_file_atomically(const std::filesystem::path& file, std::string_view contents);

}  // namespace mrsim
