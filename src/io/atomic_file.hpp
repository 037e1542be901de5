#pragma once
// Replaces a small text file so that a reader, or a run killed at any instant, sees either the
// old or the new content, never a torn one: write a sibling temporary file, then rename it
// over the target (rename is atomic within one file system on POSIX).
#include <filesystem>
#include <string_view>

namespace mrsim {

/// Writes `contents` to `file` atomically. Throws RunError naming the file on failure; the
/// temporary file is removed and `file` is left untouched in that case.
void write_file_atomically(const std::filesystem::path& file, std::string_view contents);

}  // namespace mrsim
