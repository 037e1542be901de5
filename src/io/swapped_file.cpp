#include "io/swapped_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace mrsim {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, std::string_view what, int err) {
  throw RunError("cannot write " + file.string() + ": " + std::string(what) + ": " +
                 std::strerror(err));
}

// `contents` as the whole of `spare`, written over what it held (no truncation to 0 first: ext4
// would then write the data out on close) and cut to their length.
void overwrite(const std::filesystem::path& file, const std::filesystem::path& spare,
               std::string_view contents) {
  const int fd = ::open(spare.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) fail(file, "open " + spare.string(), errno);
  std::size_t done = 0;
  while (done < contents.size()) {
    const ssize_t n = ::pwrite(fd, contents.data() + done, contents.size() - done,
                               static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      fail(file, "write " + spare.string(), err);
    }
    done += static_cast<std::size_t>(n);
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 ||
      (static_cast<std::size_t>(st.st_size) > contents.size() &&
       ::ftruncate(fd, static_cast<off_t>(contents.size())) != 0)) {
    const int err = errno;
    ::close(fd);
    fail(file, "truncate " + spare.string(), err);
  }
  if (::close(fd) != 0) fail(file, "close " + spare.string(), errno);
}

}  // namespace

SwappedFile::SwappedFile(std::filesystem::path file)
    : file_(std::move(file)), spare_(file_.string() + ".spare") {}

SwappedFile::~SwappedFile() {
  std::error_code ignored;
  std::filesystem::remove(spare_, ignored);
}

void SwappedFile::write(std::string_view contents) {
  overwrite(file_, spare_, contents);
  if (::renameat2(AT_FDCWD, spare_.c_str(), AT_FDCWD, file_.c_str(), RENAME_EXCHANGE) == 0)
    return;
  // No file yet (the first write), or a file system without the exchange: a plain rename, and
  // the next write makes a new spare.
  if (errno != ENOENT && errno != EINVAL && errno != ENOSYS && errno != EOPNOTSUPP)
    fail(file_, "exchange with " + spare_.string(), errno);
  if (std::rename(spare_.c_str(), file_.c_str()) != 0)
    fail(file_, "rename from " + spare_.string(), errno);
}

}  // namespace mrsim
