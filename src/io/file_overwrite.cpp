#include "io/file_overwrite.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace mrsim {
namespace {

int write_all(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n =
        ::pwrite(fd, bytes.data() + done, bytes.size() - done, static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

int cut_to(int fd, std::size_t size) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return errno;
  if (static_cast<std::size_t>(st.st_size) > size && ::ftruncate(fd, static_cast<off_t>(size)) != 0)
    return errno;
  return 0;
}

}  // namespace

int overwrite_and_close(int fd, std::string_view bytes) {
  int error = write_all(fd, bytes);
  if (error == 0) error = cut_to(fd, bytes.size());
  if (::close(fd) != 0 && error == 0) error = errno;
  return error;
}

}  // namespace mrsim
