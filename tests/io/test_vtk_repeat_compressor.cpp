// FrameCompressor: a block the same as in the frame before gets the bytes it had then, which are
// the bytes VTK's own compressor gives; any other block is compressed.
#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkZLibDataCompressor.h>

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/vtk_repeat_compressor.hpp"

namespace mrsim {
namespace {

std::vector<unsigned char> sample_block(std::size_t size, unsigned seed) {
  std::vector<unsigned char> b(size);
  std::uint32_t x = seed * 2654435761u + 1;
  for (std::size_t i = 0; i < size; ++i) {
    x = x * 1664525u + 1013904223u;
    b[i] = static_cast<unsigned char>(i % 7 == 0 ? x >> 24 : i / 64);  // partly compressible
  }
  return b;
}

std::vector<unsigned char> compress(vtkDataCompressor* c, const std::vector<unsigned char>& raw) {
  vtkSmartPointer<vtkUnsignedCharArray> out;
  out.TakeReference(c->Compress(raw.data(), raw.size()));
  EXPECT_NE(out, nullptr);
  if (out == nullptr) return {};
  return {out->GetPointer(0), out->GetPointer(0) + out->GetNumberOfValues()};
}

std::vector<unsigned char> uncompress(vtkDataCompressor* c, const std::vector<unsigned char>& packed,
                                      std::size_t size) {
  vtkSmartPointer<vtkUnsignedCharArray> out;
  out.TakeReference(c->Uncompress(packed.data(), packed.size(), size));
  EXPECT_NE(out, nullptr);
  if (out == nullptr) return {};
  return {out->GetPointer(0), out->GetPointer(0) + out->GetNumberOfValues()};
}

// What VTK's writer would have used: its own compressor at the frames' level.
vtkSmartPointer<vtkDataCompressor> vtks_own(FrameCompression kind) {
  vtkSmartPointer<vtkDataCompressor> c;
  if (kind == FrameCompression::Lz4) c = vtkSmartPointer<vtkLZ4DataCompressor>::New();
  if (kind == FrameCompression::Zlib) c = vtkSmartPointer<vtkZLibDataCompressor>::New();
  c->SetCompressionLevel(kind == FrameCompression::Lz4 ? 5 : 1);
  return c;
}

class FrameCompressorKinds : public ::testing::TestWithParam<FrameCompression> {};

TEST_P(FrameCompressorKinds, RepeatedBlocksGetVtksOwnBytesChangedOnesAreCompressedAgain) {
  FrameCompressor ours(GetParam());
  auto theirs = vtks_own(GetParam());
  ASSERT_NE(ours.get(), nullptr);
  // The name the pieces carry, which readers instantiate to decompress.
  EXPECT_STREQ(ours.get()->GetClassName(), theirs->GetClassName());
  const auto a = sample_block(32768, 1), b = sample_block(32768, 2), c = sample_block(4000, 3);
  auto b_last_changed = b;
  b_last_changed.back() ^= 1;  // differs in its last byte only: must not be taken for b
  const std::vector<std::vector<std::vector<unsigned char>>> frames = {
      {a, b, c}, {a, b, c}, {a, b_last_changed, c}, {c, a, b}};
  const std::size_t reused_per_frame[] = {0, 3, 2, 0};
  std::size_t reused = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    ours.begin_frame();
    for (const auto& raw : frames[f]) {
      const auto packed = compress(ours.get(), raw);
      EXPECT_EQ(packed, compress(theirs, raw)) << "frame " << f;
      EXPECT_EQ(uncompress(theirs, packed, raw.size()), raw) << "frame " << f;
    }
    reused += reused_per_frame[f];
    EXPECT_EQ(ours.blocks().reused(), reused) << "frame " << f;
  }
  EXPECT_EQ(ours.blocks().compressed(), 3u + 0u + 1u + 3u);
}

INSTANTIATE_TEST_SUITE_P(VtkRepeatCompressor, FrameCompressorKinds,
                         ::testing::Values(FrameCompression::Lz4, FrameCompression::Zlib),
                         [](const auto& info) {
                           return std::string(info.param == FrameCompression::Lz4 ? "Lz4" : "Zlib");
                         });

TEST(VtkRepeatCompressor, UncompressedFramesHaveNoCompressor) {
  EXPECT_EQ(FrameCompressor(FrameCompression::None).get(), nullptr);
}

TEST(VtkRepeatCompressor, ABlockNumberPastTheLastFrameIsCompressed) {
  RepeatedBlocks blocks;
  const auto a = sample_block(100, 4);
  std::vector<unsigned char> out(200);
  blocks.begin_frame();
  EXPECT_EQ(blocks.reuse(a.data(), a.size(), out.data()), 0u);
  const unsigned char packed[] = {1, 2, 3};
  blocks.keep(a.data(), a.size(), packed, 3);
  blocks.begin_frame();
  EXPECT_EQ(blocks.reuse(a.data(), a.size(), out.data()), 3u);
  EXPECT_EQ(out[2], 3);
  EXPECT_EQ(blocks.reuse(a.data(), a.size(), out.data()), 0u);  // block 1: none kept
  EXPECT_EQ(blocks.reuse(a.data(), a.size() - 1, out.data()), 0u);
}

}  // namespace
}  // namespace mrsim
