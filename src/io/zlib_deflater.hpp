#pragma once
// zlib streams of HDF5's deflate filter, made with one z_stream kept for the whole run: HDF5's
// own filter calls compress2(), which sets up zlib anew for every chunk (some 100 000
// instructions, its 256 KiB of tables allocated and cleared) where the data of a status row is
// a few kilobytes. deflateReset() keeps the tables. Same level, window and memory settings as
// compress2(); with zlib's default strategy, the same bytes as HDF5 writes.
#include <span>
#include <string>
#include <vector>

#include <zlib.h>

namespace mrsim::h5 {

class ZlibDeflater {
 public:
  /// `strategy`: zlib's (Z_DEFAULT_STRATEGY, Z_RLE...).
  explicit ZlibDeflater(int level, int strategy = Z_DEFAULT_STRATEGY);
  ~ZlibDeflater();
  ZlibDeflater(const ZlibDeflater&) = delete;
  ZlibDeflater& operator=(const ZlibDeflater&) = delete;

  /// `data` as one zlib stream; valid until the next call. std::runtime_error if zlib fails.
  /// The same bytes as the last call's give its stream again without deflating: a fine level's
  /// status row changes only at the frames that split or merge (45 of liver_probe's 71 rows
  /// are the row before them), and deflating a row is ~50 000 instructions.
  std::span<const unsigned char> compress(std::span<const unsigned char> data);

 private:
  z_stream stream_{};
  std::vector<unsigned char> out_;
  std::vector<unsigned char> last_in_;  // the last call's data, its stream out_[0, last_out_)
  std::size_t last_out_ = 0;
  bool has_last_ = false;
};

}  // namespace mrsim::h5
