#include "io/file_recycler.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "io/file_overwrite.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, int error) {
  throw RunError("cannot write " + file.string() + ": " + std::generic_category().message(error) +
                 " (errno " + std::to_string(error) + ")");
}

// A regular file no other name links to: written over, nobody else sees it change.
bool sole_regular_file(const fs::path& file) {
  struct stat st {};
  return ::lstat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1;
}

}  // namespace

FileRecycler::FileRecycler(fs::path pool) : pool_(std::move(pool)) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(pool_, ec)) {
    const fs::file_type type = entry.symlink_status(ec).type();
    if (type == fs::file_type::directory)
      dirs_.push_back(entry.path());
    else if (type == fs::file_type::regular && sole_regular_file(entry.path()))
      files_.push_back(entry.path());
  }
}

void FileRecycler::make_directory(const fs::path& dir) {
  std::error_code ec;
  while (!dirs_.empty()) {
    const fs::path old = std::move(dirs_.back());
    dirs_.pop_back();
    fs::rename(old, dir, ec);
    if (ec) continue;
    // Its files are the next ones written over; anything else goes back to the pool.
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
      if (sole_regular_file(entry.path())) {
        files_.push_back(entry.path());
        continue;
      }
      std::error_code moved;
      fs::rename(entry.path(), returned_path(), moved);
      if (moved) fs::remove_all(entry.path(), moved);  // the old frames' own, removed anyway
      if (moved) throw RunError("cannot clear " + entry.path().string() + ": " + moved.message());
    }
    return;
  }
  fs::create_directory(dir, ec);
  if (ec) throw RunError("cannot write " + dir.string() + ": " + ec.message());
}

// A new name in the pool for a file given back to it.
fs::path FileRecycler::returned_path() {
  return pool_ / ("returned_" + std::to_string(returned_++));
}

bool FileRecycler::take_file(const fs::path& file) {
  // A folder taken may hold an old file of this very name (the old frame of the same number):
  // that one is written over where it is; renaming another onto it would drop it from the
  // pool's count while its name stayed listed.
  const auto same = std::find_if(files_.begin(), files_.end(), [&](const fs::path& old) {
    return old.native() == file.native();
  });
  if (same != files_.end()) {
    files_.erase(same);
    return true;
  }
  std::error_code ec;
  while (!files_.empty()) {
    const fs::path old = std::move(files_.back());
    files_.pop_back();
    fs::rename(old, file, ec);
    if (!ec) return true;
  }
  return false;
}

void FileRecycler::write_file(const fs::path& file, std::string_view bytes) {
  if (take_file(file)) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC | O_NOFOLLOW);
    struct stat st {};
    if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1) {
      if (const int error = overwrite_and_close(fd, bytes); error != 0) fail(file, error);
      ++reused_;
      return;
    }
    // Linked elsewhere since the pool was listed: it goes back, untouched, and a new file is
    // made.
    if (fd >= 0) ::close(fd);
    std::error_code ec;
    fs::rename(file, returned_path(), ec);
    if (ec) fail(file, EEXIST);
  }
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(file, errno);
  if (const int error = overwrite_and_close(fd, bytes); error != 0) fail(file, error);
}

void FileRecycler::release(const fs::path& dir) {
  for (fs::path& file : files_) {
    if (file.parent_path() != dir) continue;
    const fs::path back = returned_path();
    std::error_code ec;
    fs::rename(file, back, ec);
    if (ec) {  // never publish a stale file with the frame: remove it, or fail
      fs::remove(file, ec);
      if (ec) throw RunError("cannot clear " + file.string() + ": " + ec.message());
    }
    file = back;
  }
}

}  // namespace mrsim
