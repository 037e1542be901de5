#pragma once
// The frames' compressor, which compresses a block only when it differs from the block it
// stands for in the frame before. A frame's cells (connectivity, offsets, types), and its masses,
// statuses and ownership between topology changes, are the same bytes from frame to frame; VTK's
// XML writer compresses every one of them again (a third of a liver_probe frame's LZ4 time).
// Blocks come in the same order every frame (the same pieces, arrays and sizes), so block k of a
// frame is compared byte for byte with block k of the one before, and, when equal, handed the
// compressed bytes it had then: the same bytes VTK's own compressor gives, since LZ4 and zlib are
// deterministic. It is a vtkLZ4DataCompressor or vtkZLibDataCompressor to the writer (the
// class name the pieces carry); memory: one frame's blocks, raw and compressed.
#include <vtkSmartPointer.h>

#include <cstddef>
#include <memory>
#include <vector>

#include "io/frame_compression.hpp"

class vtkDataCompressor;

namespace mrsim {

/// Block k of the previous frame, raw and compressed, for each k.
class RepeatedBlocks {
 public:
  /// Block numbers start again at 0: the next block compressed is the new frame's first.
  void begin_frame() { next_ = 0; }
  /// The compressed bytes of block `next` when it holds `raw` again (copied to `out`, their
  /// size returned), else 0; either way the block number moves on.
  std::size_t reuse(const unsigned char* raw, std::size_t size, unsigned char* out);
  /// Keeps what the block just compressed by the compressor itself holds.
  void keep(const unsigned char* raw, std::size_t size, const unsigned char* packed,
            std::size_t packed_size);
  std::size_t reused() const { return reused_; }
  std::size_t compressed() const { return compressed_; }

 private:
  struct Block {
    std::vector<unsigned char> raw, packed;
  };
  std::vector<Block> blocks_;
  std::size_t next_ = 0;
  std::size_t reused_ = 0, compressed_ = 0;  // blocks, over the whole series
};

/// The compressor a series' writers share: of the frames' kind, at the level they use (VTK's
/// default 5 for LZ4, 1 for zlib), none for uncompressed frames.
class FrameCompressor {
 public:
  explicit FrameCompressor(FrameCompression kind);
  ~FrameCompressor();
  void begin_frame() { blocks_->begin_frame(); }
  vtkDataCompressor* get() const;  // nullptr: no compression
  const RepeatedBlocks& blocks() const { return *blocks_; }

 private:
  std::shared_ptr<RepeatedBlocks> blocks_;
  vtkSmartPointer<vtkDataCompressor> compressor_;
};

}  // namespace mrsim
