#include "io/atomic_file.hpp"

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

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view contents) {
  // The temporary lives beside the target so that the rename never crosses file systems.
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  try {
    write_whole_file(temporary, contents);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, file, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw RunError("cannot write " + file.string() + ": rename from " + temporary.string() +
                   " failed: " + ec.message());
  }
}

}  // namespace mrsim
