#pragma once
// ParaView time series (product.md "What a run writes"): frames/frame_NNNNNN.vtm with one
// UnstructuredGrid block per level (binary, LZ4 unless asked otherwise), optionally followed by
// the PolyData blocks `surface` (the object's skin) and `tool`, and frames.pvd listing every
// frame with its simulated time at full precision. The .pvd is replaced after each frame, whole
// and atomically (io/swapped_file.hpp), so a run killed or failed mid-way leaves a valid series.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/frame_data.hpp"
#include "io/frame_compression.hpp"
#include "io/frame_series_writer.hpp"

class vtkMultiBlockDataSet;

namespace mrsim {

class FrameCompressor;
class LevelGrids;
class PieceWriters;
class SwappedFile;
class FileRecycler;

class VtkSeriesWriter final : public FrameSeriesWriter {
 public:
  explicit VtkSeriesWriter(std::filesystem::path out_dir,
                           FrameCompression compression = FrameCompression::Lz4);
  ~VtkSeriesWriter() override;
  // Not movable: the destructor removes the staging folder of this writer's series.
  VtkSeriesWriter(const VtkSeriesWriter&) = delete;
  VtkSeriesWriter& operator=(const VtkSeriesWriter&) = delete;
  /// Writes one frame (all levels, then the `surface` block when `surface` is given and the
  /// `tool` block when `tools` is not empty) and updates frames.pvd. Throws RunError on I/O
  /// failure, std::invalid_argument (before writing anything) on inconsistent sizes.
  void write_frame(int frame_index, double time, std::span<const LevelFrameView> levels,
                   const SurfaceFrameView* surface = nullptr,
                   std::span<const ToolFrameView> tools = {}) override;
  int frames_written() const { return static_cast<int>(entries_.size()); }
  /// Compressed blocks taken unchanged from the frame before (io/vtk_repeat_compressor.hpp).
  std::size_t reused_blocks() const;
  /// Files of the previous run's frames written over instead of made (io/file_recycler.hpp).
  std::size_t recycled_files() const;
  /// Pieces left to VTK's own XML writer (io/vtk_piece_writers.hpp).
  std::size_t pieces_written_by_vtk() const;
  /// Goes on with the series of a run resumed after frame `last` (mrsim run --resume): `kept`
  /// (index, time) are its frames up to there, each of which must be complete on disk (else
  /// InputError). Every later frame and any partial one are removed (a run killed after its
  /// checkpoint wrote them), and frames.pvd lists the kept frames.
  void resume(std::span<const std::pair<int, double>> kept, int last) override;

 private:
  struct Entry { int index; double time; std::filesystem::path file; };
  void write_pvd() const;
  void write_complete(const std::filesystem::path& relative, vtkMultiBlockDataSet* blocks);
  std::filesystem::path out_dir_;
  std::vector<Entry> entries_;
  std::unique_ptr<LevelGrids> grids_;  // each level's grid, its cells built once
  std::unique_ptr<FrameCompressor> compressor_;  // compresses the blocks that changed
  std::unique_ptr<PieceWriters> writers_;  // each block's XML writer, kept from frame to frame
  std::unique_ptr<SwappedFile> pvd_;  // frames.pvd, replaced after each frame
  std::unique_ptr<FileRecycler> recycler_;  // the previous run's frame files, written over
  std::string piece_buffer_;  // each piece's bytes, its capacity kept from piece to piece
};

}  // namespace mrsim
