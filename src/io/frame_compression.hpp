#pragma once
namespace mrsim {

// How the frames' binary data is compressed (output.compression, docs/output.md).
enum class FrameCompression { Lz4, Zlib, None };

}  // namespace mrsim
