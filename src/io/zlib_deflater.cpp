#include "io/zlib_deflater.hpp"

#include <algorithm>
#include <stdexcept>

namespace mrsim::h5 {

ZlibDeflater::ZlibDeflater(int level, int strategy) {
  constexpr int kWindowBits = 15, kMemoryLevel = 8;  // deflateInit()'s, as compress2() uses
  if (deflateInit2(&stream_, level, Z_DEFLATED, kWindowBits, kMemoryLevel, strategy) != Z_OK)
    throw std::runtime_error("zlib: cannot set up deflate at level " + std::to_string(level));
}

ZlibDeflater::~ZlibDeflater() { deflateEnd(&stream_); }

std::span<const unsigned char> ZlibDeflater::compress(std::span<const unsigned char> data) {
  if (has_last_ && std::ranges::equal(data, last_in_)) return {out_.data(), last_out_};
  has_last_ = false;  // until this call's stream is whole
  if (deflateReset(&stream_) != Z_OK) throw std::runtime_error("zlib: cannot reset deflate");
  out_.resize(deflateBound(&stream_, static_cast<uLong>(data.size())));
  // zlib's interface takes a non-const input pointer; it does not write through it.
  stream_.next_in = const_cast<unsigned char*>(data.data());
  stream_.avail_in = static_cast<uInt>(data.size());
  stream_.next_out = out_.data();
  stream_.avail_out = static_cast<uInt>(out_.size());
  // deflateBound() is room for the whole stream, so one call finishes it.
  if (deflate(&stream_, Z_FINISH) != Z_STREAM_END)
    throw std::runtime_error("zlib: deflate did not finish its stream");
  last_in_.assign(data.begin(), data.end());
  last_out_ = out_.size() - stream_.avail_out;
  has_last_ = true;
  return {out_.data(), last_out_};
}

}  // namespace mrsim::h5
