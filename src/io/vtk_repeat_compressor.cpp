#include "io/vtk_repeat_compressor.hpp"

#include <vtkLZ4DataCompressor.h>
#include <vtkZLibDataCompressor.h>

#include <cstring>
#include <utility>

namespace mrsim {

std::size_t RepeatedBlocks::reuse(const unsigned char* raw, std::size_t size, unsigned char* out) {
  if (next_ >= blocks_.size()) return 0;
  const Block& b = blocks_[next_];
  if (b.raw.size() != size || std::memcmp(b.raw.data(), raw, size) != 0) return 0;
  std::memcpy(out, b.packed.data(), b.packed.size());
  ++next_;
  ++reused_;
  return b.packed.size();
}

void RepeatedBlocks::keep(const unsigned char* raw, std::size_t size, const unsigned char* packed,
                          std::size_t packed_size) {
  if (next_ >= blocks_.size()) blocks_.resize(next_ + 1);
  Block& b = blocks_[next_++];
  b.raw.assign(raw, raw + size);
  b.packed.assign(packed, packed + packed_size);
  ++compressed_;
}

namespace {

// Without vtkTypeMacro of its own: to the writer, and in the file's `compressor` attribute, it
// is its base, whose reader decompresses it.
template <class Base>
class RepeatCompressor : public Base {
 public:
  static RepeatCompressor* make(std::shared_ptr<RepeatedBlocks> blocks) {
    auto* c = new RepeatCompressor(std::move(blocks));
    c->InitializeObjectBase();
    return c;
  }

 protected:
  explicit RepeatCompressor(std::shared_ptr<RepeatedBlocks> blocks) : blocks_(std::move(blocks)) {}

  size_t CompressBuffer(unsigned char const* raw, size_t size, unsigned char* out,
                        size_t space) override {
    if (const std::size_t n = blocks_->reuse(raw, size, out); n > 0) return n;
    const size_t n = Base::CompressBuffer(raw, size, out, space);
    if (n > 0) blocks_->keep(raw, size, out, n);
    return n;
  }

 private:
  std::shared_ptr<RepeatedBlocks> blocks_;
};

}  // namespace

FrameCompressor::FrameCompressor(FrameCompression kind)
    : blocks_(std::make_shared<RepeatedBlocks>()) {
  switch (kind) {
    case FrameCompression::Lz4:
      // VTK's writer gives the compressor it makes its own level, 5 unless set.
      compressor_.TakeReference(RepeatCompressor<vtkLZ4DataCompressor>::make(blocks_));
      compressor_->SetCompressionLevel(5);
      break;
    case FrameCompression::Zlib:
      compressor_.TakeReference(RepeatCompressor<vtkZLibDataCompressor>::make(blocks_));
      compressor_->SetCompressionLevel(1);
      break;
    case FrameCompression::None:
      break;
  }
}

FrameCompressor::~FrameCompressor() = default;

vtkDataCompressor* FrameCompressor::get() const { return compressor_; }

}  // namespace mrsim
