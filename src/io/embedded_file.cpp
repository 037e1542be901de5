#include "io/embedded_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_group.hpp"

namespace mrsim::h5 {
namespace {

// Blocks of 4 MiB: large enough to make the copy one pass at disk speed, small in memory.
constexpr hsize_t kBlock = hsize_t{1} << 22;

[[noreturn]] void fail(const std::filesystem::path& file, const char* what, int err) {
  throw RunError("cannot " + std::string(what) + " " + file.string() + ": " + std::strerror(err));
}

class CFile {
 public:
  CFile(const std::filesystem::path& file, const char* mode) : file_(file) {
    f_ = std::fopen(file.c_str(), mode);
    if (f_ == nullptr) fail(file, mode[0] == 'r' ? "read" : "write", errno);
  }
  ~CFile() {
    if (f_ != nullptr) std::fclose(f_);
  }
  CFile(const CFile&) = delete;
  CFile& operator=(const CFile&) = delete;
  std::FILE* get() const { return f_; }
  // Flushed and closed, with the reason when either fails (a full disk shows here).
  void close() {
    const bool flushed = std::fflush(f_) == 0;
    const int err = errno;
    const int closed = std::fclose(f_);
    f_ = nullptr;
    if (!flushed) fail(file_, "write", err);
    if (closed != 0) fail(file_, "write", errno);
  }

 private:
  std::filesystem::path file_;
  std::FILE* f_ = nullptr;
};

// The selection of bytes [offset, offset + count) of a 1-D dataset, and its memory twin.
struct Slab {
  Handle file_space, memory_space;
};

Slab slab(hid_t dataset, hsize_t offset, hsize_t count, Where where) {
  Slab s{checked(H5Dget_space(dataset), H5Sclose, where, "get dataspace"),
         checked(H5Screate_simple(1, &count, nullptr), H5Sclose, where, "create dataspace")};
  check(H5Sselect_hyperslab(s.file_space.get(), H5S_SELECT_SET, &offset, nullptr, &count, nullptr),
        where, "select bytes");
  return s;
}

}  // namespace

void embed_file(hid_t parent, const std::string& name, const std::filesystem::path& file,
                Where where) {
  std::error_code ec;
  const auto size = static_cast<hsize_t>(std::filesystem::file_size(file, ec));
  if (ec) throw RunError("cannot read " + file.string() + ": " + ec.message());
  CFile in(file, "rb");
  Handle space = checked(H5Screate_simple(1, &size, nullptr), H5Sclose, where, "create dataspace");
  Handle properties =
      checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, where, "create dataset properties");
  no_time_stamps(properties.get(), where);
  Handle dataset = checked(H5Dcreate2(parent, name.c_str(), H5T_STD_U8LE, space.get(), H5P_DEFAULT,
                                      properties.get(), H5P_DEFAULT),
                           H5Dclose, where, "create dataset");
  std::vector<unsigned char> block(static_cast<std::size_t>(std::min(size, kBlock)));
  for (hsize_t offset = 0; offset < size; offset += kBlock) {
    const hsize_t count = std::min(kBlock, size - offset);
    if (std::fread(block.data(), 1, count, in.get()) != count)
      throw RunError("cannot read " + file.string() + ": it changed while being copied");
    const Slab s = slab(dataset.get(), offset, count, where);
    check(H5Dwrite(dataset.get(), H5T_NATIVE_UCHAR, s.memory_space.get(), s.file_space.get(),
                   H5P_DEFAULT, block.data()),
          where, "write dataset");
  }
  check(dataset.close(), where, "close dataset");
}

void extract_file(hid_t parent, const std::string& name, const std::filesystem::path& file,
                  Where where) {
  Handle dataset =
      checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, where, "open dataset");
  Handle space = checked(H5Dget_space(dataset.get()), H5Sclose, where, "get dataspace");
  hsize_t size = 0;
  if (H5Sget_simple_extent_ndims(space.get()) != 1 ||
      H5Sget_simple_extent_dims(space.get(), &size, nullptr) != 1)
    throw_error(where, "read " + name + " (not 1-D)");
  replace_atomically(
      file,
      [&](const std::filesystem::path& tmp) {
        CFile out(tmp, "wb");
        std::vector<unsigned char> block(static_cast<std::size_t>(std::min(size, kBlock)));
        for (hsize_t offset = 0; offset < size; offset += kBlock) {
          const hsize_t count = std::min(kBlock, size - offset);
          const Slab s = slab(dataset.get(), offset, count, where);
          check(H5Dread(dataset.get(), H5T_NATIVE_UCHAR, s.memory_space.get(),
                        s.file_space.get(), H5P_DEFAULT, block.data()),
                where, "read dataset");
          if (std::fwrite(block.data(), 1, count, out.get()) != count) fail(tmp, "write", errno);
        }
        out.close();
      },
      Durability::Synced);
}

}  // namespace mrsim::h5
