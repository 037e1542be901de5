#pragma once
// The files of the previous run's frames, reused for the new run's instead of removed and made
// again. A run into a folder that holds a finished run takes its frames/ over (RunFolder moves it
// to frames.recycled); each new frame folder is an old one renamed, each piece and .vtm an old
// file renamed and written over. Why: on ext4 without a journal (this project's CI and
// development hosts), making a file after many were removed scans past every inode freed in the
// last one to six minutes (ext4's recently_deleted()), 0.1 to 1 ms a file, most of the time
// liver_thesis' frames took (perf: __ext4_new_inode 19 % of a liver_probe run with frames); a
// rename is about 0.04 ms. Elsewhere it saves a create and an unlink per file.
//
// Only regular files that no other name links to are written over (a frame kept with `cp -al`
// or a symbolic link to a user's file stays as it was: such a file is left in the pool and
// removed with it); what is left of the pool when the run ends is removed (RunFolder).
#include <cstddef>
#include <filesystem>
#include <string_view>
#include <vector>

namespace mrsim {

/// Where RunFolder puts the finished run's frames/ for the new run's to be written over.
inline constexpr const char* kRecycledFramesDir = "frames.recycled";

class FileRecycler {
 public:
  /// Takes the folders and files directly in `pool` (none if it does not exist).
  explicit FileRecycler(std::filesystem::path pool);

  /// Makes the folder `dir` (its parent exists): an old frame folder renamed, else a new one.
  /// Throws RunError naming `dir` when neither can be done.
  void make_directory(const std::filesystem::path& dir);
  /// Writes `bytes` as the whole of the file `file` (which does not exist): an old file renamed
  /// and written over, else a new file. Throws RunError naming `file` on failure.
  void write_file(const std::filesystem::path& file, std::string_view bytes);
  /// Before `dir` is published: the old files still in it go back to the pool, so that the
  /// folder holds only what was written into it since make_directory.
  void release(const std::filesystem::path& dir);

  /// Files written over instead of made (over the series), for tests and the benchmark.
  std::size_t reused() const { return reused_; }

 private:
  bool take_file(const std::filesystem::path& file);
  std::filesystem::path returned_path();
  std::filesystem::path pool_;
  std::vector<std::filesystem::path> dirs_;   // old folders in the pool
  std::vector<std::filesystem::path> files_;  // old files, in the pool or in a folder taken
  std::size_t returned_ = 0, reused_ = 0;
};

}  // namespace mrsim
