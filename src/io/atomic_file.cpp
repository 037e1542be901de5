#include "io/atomic_file.hpp"

#include <fcntl.h>
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

// C stdio rather than iostreams: errno tells the user *why* (disk full, permission denied).
void write_whole_file(const std::filesystem::path& file, std::string_view contents) {
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (out == nullptr) fail(file, "open", errno);
  const std::size_t written = std::fwrite(contents.data(), 1, contents.size(), out);
  const int write_errno = errno;
  const bool flushed = std::fflush(out) == 0;
  const int flush_errno = errno;
  const bool closed = std::fclose(out) == 0;
  if (written != contents.size()) fail(file, "write", write_errno);
  if (!flushed) fail(file, "flush", flush_errno);
  if (!closed) fail(file, "close", errno);
}

// The data reach the disk before the rename makes them the file.
void sync_file(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int err = errno;
    if (fd >= 0) ::close(fd);
    fail(file, "sync", err);
  }
  ::close(fd);
}

}  // namespace

void replace_atomically(const std::filesystem::path& file,
                        const std::function<void(const std::filesystem::path& tmp)>& write,
                        Durability durability) {
  // The temporary lives beside the target so that the rename never crosses file systems.
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  try {
    write(temporary);
    if (durability == Durability::Synced) sync_file(temporary);
    std::error_code ec;
    std::filesystem::rename(temporary, file, ec);
    if (ec)
      throw RunError("cannot write " + file.string() + ": rename from " + temporary.string() +
                     " failed: " + ec.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& file, std::string_view contents) {
  replace_atomically(file,
                     [&](const std::filesystem::path& tmp) { write_whole_file(tmp, contents); });
}

}  // namespace mrsim
