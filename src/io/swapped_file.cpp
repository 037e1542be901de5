#include "io/swapped_file.hpp"

#include <fcntl.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "io/file_overwrite.hpp"

namespace mrsim {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, std::string_view what, int err) {
  throw RunError("cannot write " + file.string() + ": " + std::string(what) + ": " +
                 std::strerror(err));
}

// `contents` as the whole of `spare`, written over what it held.
void overwrite(const std::filesystem::path& file, const std::filesystem::path& spare,
               std::string_view contents) {
  const int fd = ::open(spare.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) fail(file, "open " + spare.string(), errno);
  if (const int error = overwrite_and_close(fd, contents); error != 0)
    fail(file, "write " + spare.string(), error);
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
