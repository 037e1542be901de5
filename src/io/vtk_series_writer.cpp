#include "io/vtk_series_writer.hpp"

#include <vtkCompositeDataSet.h>
#include <vtkDataCompressor.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "core/error.hpp"
#include "io/frame_data_check.hpp"
#include "io/pvd_file.hpp"
#include "io/file_recycler.hpp"
#include "io/swapped_file.hpp"
#include "io/vtk_level_grid.hpp"
#include "io/vtk_repeat_compressor.hpp"
#include "io/vtk_surface_blocks.hpp"
#include "io/vtk_piece_writers.hpp"

namespace mrsim {
namespace {

constexpr const char* kFramesDir = "frames";
constexpr const char* kPvdName = "frames.pvd";
constexpr const char* kPartialDir = ".partial";  // frames/.partial: a frame being written

// frames/frame_NNNNNN.vtm, relative to the output folder (the form the .pvd refers to).
std::filesystem::path frame_file(int frame_index) {
  std::array<char, 32> name{};
  std::snprintf(name.data(), name.size(), "frame_%06d.vtm", frame_index);
  return std::filesystem::path(kFramesDir) / name.data();
}

// Everything the frame holds, checked before any file is written: a refused frame leaves
// neither a .vtm nor a .pvd entry behind.
void check_frame(std::span<const LevelFrameView> levels, const SurfaceFrameView* surface,
                 std::span<const ToolFrameView> tools) {
  if (levels.empty()) throw std::invalid_argument("write_frame: no level to write");
  for (std::size_t k = 0; k < levels.size(); ++k) check_level_view(levels[k], static_cast<int>(k));
  if (surface != nullptr) check_surface_view(*surface);
  for (std::size_t k = 0; k < tools.size(); ++k) check_tool_view(tools[k], static_cast<int>(k));
}

void append_block(vtkMultiBlockDataSet* blocks, vtkDataObject* block, const std::string& name) {
  const unsigned index = blocks->GetNumberOfBlocks();
  blocks->SetBlock(index, block);
  blocks->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name.c_str());
}

// Levels first, then surface and tool: readers look blocks up by name, and the level blocks
// keep the positions they had before the other two existed.
vtkSmartPointer<vtkMultiBlockDataSet> frame_blocks(LevelGrids& grids,
                                                   std::span<const LevelFrameView> levels,
                                                   const SurfaceFrameView* surface,
                                                   std::span<const ToolFrameView> tools,
                                                   double time) {
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  for (std::size_t k = 0; k < levels.size(); ++k) {
    append_block(blocks, grids.update(k, levels[k], time), "level_" + std::to_string(k));
  }
  if (surface != nullptr) append_block(blocks, make_surface_block(*surface, time), "surface");
  if (!tools.empty()) append_block(blocks, make_tool_block(tools, time), "tool");
  return blocks;
}

}  // namespace

namespace {

// The frame as vtkXMLMultiBlockDataWriter lays it out (a .vtm naming one file per block in a
// folder of the frame's name, the same bytes in every piece), each piece written at once.
void write_vtm(const std::filesystem::path& file, vtkMultiBlockDataSet* blocks,
               vtkDataCompressor* compressor, PieceWriters& writers, FileRecycler& recycler,
               std::string& buffer) {
  namespace fs = std::filesystem;
  const std::string stem = file.stem().string();
  recycler.make_directory(file.parent_path() / stem);
  std::string vtm = "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
                    "byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  // The name VTK's own writers give it: the class readers instantiate to decompress.
  if (compressor != nullptr)
    vtm += std::string(" compressor=\"") + compressor->GetClassName() + "\"";
  vtm += ">\n  <vtkMultiBlockDataSet>\n";
  for (unsigned k = 0; k < blocks->GetNumberOfBlocks(); ++k) {
    vtkDataObject* block = blocks->GetBlock(k);
    const bool grid = vtkUnstructuredGrid::SafeDownCast(block) != nullptr;
    const std::string piece = stem + "/" + stem + "_" + std::to_string(k) + (grid ? ".vtu" : ".vtp");
    const fs::path path = file.parent_path() / piece;
    writers.write(k, block, compressor, path.string(), buffer);
    recycler.write_file(path, buffer);
    const char* name = blocks->GetMetaData(k)->Get(vtkCompositeDataSet::NAME());
    vtm += "    <DataSet index=\"" + std::to_string(k) + "\" name=\"" + name + "\" file=\"" + piece +
           "\"/>\n";
  }
  vtm += "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
  recycler.write_file(file, vtm);
}

}  // namespace

VtkSeriesWriter::~VtkSeriesWriter() {
  // The staging folder is empty between frames; a run that ends (however) leaves none. One
  // holding a half-written frame (the run failed while writing it) is not empty and stays.
  std::error_code ec;
  std::filesystem::remove(out_dir_ / kFramesDir / kPartialDir, ec);
}

VtkSeriesWriter::VtkSeriesWriter(std::filesystem::path out_dir, FrameCompression compression)
    : out_dir_(std::move(out_dir)),
      grids_(std::make_unique<LevelGrids>()),
      compressor_(std::make_unique<FrameCompressor>(compression)),
      writers_(std::make_unique<PieceWriters>()),
      pvd_(std::make_unique<SwappedFile>(out_dir_ / kPvdName)),
      recycler_(std::make_unique<FileRecycler>(out_dir_ / kRecycledFramesDir)) {
  // Created up front so that an unusable output folder fails the run before any step.
  std::error_code ec;
  std::filesystem::create_directories(out_dir_ / kFramesDir, ec);
  if (ec) {
    throw RunError("cannot create " + (out_dir_ / kFramesDir).string() + ": " + ec.message());
  }
}

std::size_t VtkSeriesWriter::reused_blocks() const { return compressor_->blocks().reused(); }

std::size_t VtkSeriesWriter::recycled_files() const { return recycler_->reused(); }

std::size_t VtkSeriesWriter::pieces_written_by_vtk() const { return writers_->written_by_vtk(); }

void VtkSeriesWriter::write_frame(int frame_index, double time,
                                  std::span<const LevelFrameView> levels,
                                  const SurfaceFrameView* surface,
                                  std::span<const ToolFrameView> tools) {
  check_frame(levels, surface, tools);
  const std::filesystem::path relative = frame_file(frame_index);
  write_complete(relative, frame_blocks(*grids_, levels, surface, tools, time));
  // Listed only once its file is complete: the .pvd never names a half-written frame.
  entries_.push_back({frame_index, time, relative});
  write_pvd();
}

// The frame is written in frames/.partial/ (the same relative layout, so the .vtm's references
// to its pieces hold) and moved under its final names once complete, pieces first, the .vtm
// last: a run killed while writing leaves only frames/.partial behind, never a half-written
// file under a final name (issue 18 defect 8; the next run into the folder removes frames/).
// frames/.partial is kept, empty, between frames (create_directories finds it there):
// making and removing it every frame cost two more inode changes a frame, and on ext4 without
// a journal each removed inode slows the file creations of the next minutes
// (docs/performance.md).
void VtkSeriesWriter::write_complete(const std::filesystem::path& relative,
                                     vtkMultiBlockDataSet* blocks) {
  namespace fs = std::filesystem;
  const fs::path frames = out_dir_ / kFramesDir, partial = frames / kPartialDir;
  const fs::path vtm = relative.filename(), pieces = fs::path(vtm).replace_extension();
  std::error_code ec;
  fs::create_directories(partial, ec);
  if (ec)
    throw RunError("cannot write " + (out_dir_ / relative).string() + ": cannot create " +
                   partial.string() + ": " + ec.message());
  compressor_->begin_frame();
  write_vtm(partial / vtm, blocks, compressor_->get(), *writers_, *recycler_, piece_buffer_);
  recycler_->release(partial / pieces);
  if (fs::exists(partial / pieces, ec)) fs::rename(partial / pieces, frames / pieces, ec);
  if (!ec) fs::rename(partial / vtm, frames / vtm, ec);
  if (ec)
    throw RunError("cannot move " + (partial / vtm).string() + " into " + frames.string() + ": " +
                   ec.message());
}

void VtkSeriesWriter::resume(std::span<const std::pair<int, double>> kept, int last) {
  namespace fs = std::filesystem;
  entries_.clear();
  for (const auto& [index, time] : kept) {
    const fs::path relative = frame_file(index);
    if (!fs::is_regular_file(out_dir_ / relative))
      throw InputError("cannot resume in " + out_dir_.string() + ": " +
                       relative.generic_string() + " of frame " + std::to_string(index) +
                       " is missing");
    entries_.push_back({index, time, relative});
  }
  const fs::path frames = out_dir_ / kFramesDir;
  std::error_code ec;
  fs::remove_all(frames / kPartialDir, ec);
  for (const fs::directory_entry& e : fs::directory_iterator(frames, ec)) {
    int index = -1;
    const std::string name = e.path().filename().string();
    if (std::sscanf(name.c_str(), "frame_%d", &index) == 1 && index > last) {
      fs::remove_all(e.path(), ec);
      if (ec) throw RunError("cannot remove " + e.path().string() + ": " + ec.message());
    }
  }
  write_pvd();
}

void VtkSeriesWriter::write_pvd() const {
  std::vector<PvdEntry> pvd;
  pvd.reserve(entries_.size());
  for (const Entry& entry : entries_) pvd.push_back({entry.time, entry.file.generic_string()});
  pvd_->write(pvd_text(pvd));
}

}  // namespace mrsim
