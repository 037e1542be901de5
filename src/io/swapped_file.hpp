#pragma once
// A small file replaced after every frame (frames.pvd), atomically and without a new inode each
// time: the new content goes into a spare sibling (`file`.spare, kept from one replacement to the
// next), which then trades names with the file in one renameat2(RENAME_EXCHANGE). A reader, or a
// run killed at any instant, sees the old or the new content, never a torn one, as with a
// temporary renamed over the file (io/atomic_file.hpp); but the file system neither allocates nor
// frees an inode per frame, and ext4 does not write the replaced file's data out at once (its
// auto_da_alloc on a rename over a file). Where the exchange is not supported, the spare is
// renamed over the file and made again next time.
#include <filesystem>
#include <string_view>

namespace mrsim {

class SwappedFile {
 public:
  explicit SwappedFile(std::filesystem::path file);
  /// Removes the spare: a finished series leaves only the file.
  ~SwappedFile();
  SwappedFile(const SwappedFile&) = delete;
  SwappedFile& operator=(const SwappedFile&) = delete;

  /// Makes `contents` the file's. Throws RunError naming the file on failure; the file is then
  /// left as it was.
  void write(std::string_view contents);

  const std::filesystem::path& spare() const { return spare_; }

 private:
  std::filesystem::path file_, spare_;
};

}  // namespace mrsim
