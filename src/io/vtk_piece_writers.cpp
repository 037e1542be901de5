#include "io/vtk_piece_writers.hpp"

#include <vtkDataCompressor.h>
#include <vtkErrorCode.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "io/vtk_error_capture.hpp"

namespace mrsim {
namespace {

// liver_probe (four levels every 20 ms, 70 frames, one thread): zlib level 5 (VTK's default)
// 3.13 s of output, level 1 2.50 s for 45 MB, LZ4 about 0.9 s for 58 MB: LZ4 by default, so
// that writing frames does not keep a run from its simulated time; zlib to keep smaller files
// (io/vtk_repeat_compressor.hpp sets the levels, and compresses only the blocks that changed).
void set_compressor(vtkXMLWriter* writer, vtkDataCompressor* compressor) {
  if (compressor != nullptr)
    writer->SetCompressor(compressor);
  else
    writer->SetCompressorTypeToNone();
}

// A VTK XML writer that writes into the stream it is given: VTK's writers keep a protected
// `Stream`, used as is when set (vtkXMLWriter::OpenStream), which their own string output would
// otherwise create, copy twice when done and free for every piece.
template <class Writer>
class StreamWriter : public Writer {
 public:
  static StreamWriter* make() {
    auto* w = new StreamWriter;
    w->InitializeObjectBase();
    return w;
  }
  void write_into(std::ostream* stream) { this->Stream = stream; }
};

// One block into memory: the XML writer patches offsets by seeking back in its stream, which on
// a file is a flush and two lseek per array (1 100 writes and 1 200 seeks a liver_probe frame);
// in memory it costs nothing, and the piece is then written with one call. `buffer` (empty,
// its capacity kept from the pieces before) receives the piece: the stream writes into its
// capacity, so a frame's pieces allocate nothing once the first frame has grown it.
template <class Writer>
void piece_bytes(StreamWriter<Writer>* writer, vtkDataObject* block,
                 vtkDataCompressor* compressor, const std::string& name, std::string& buffer) {
  writer->SetInputData(block);
  set_compressor(writer, compressor);
  buffer.clear();
  std::ostringstream out(std::move(buffer));
  writer->write_into(&out);
  VtkErrorCapture errors;
  const int ok = writer->Write();
  writer->write_into(nullptr);
  writer->SetInputData(nullptr);  // the block is the frame's: the writer keeps no hold on it
  buffer = std::move(out).str();
  if (ok != 1 || writer->GetErrorCode() != vtkErrorCode::NoError || errors.any() || !out) {
    std::string reason = errors.summary();
    if (reason.empty()) reason = vtk_error_code_text(writer->GetErrorCode());
    throw RunError("cannot write " + name + ": " + reason);
  }
}

template <class Writer>
vtkSmartPointer<StreamWriter<Writer>> make_piece_writer() {
  vtkSmartPointer<StreamWriter<Writer>> writer;
  writer.TakeReference(StreamWriter<Writer>::make());
  // Raw appended binary: the smallest and fastest XML form ParaView and vtk read.
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();  // blocks over 4 GiB stay writable
  return writer;
}

template <class Writer>
StreamWriter<Writer>* kept_at(std::vector<vtkSmartPointer<StreamWriter<Writer>>>& kept,
                              unsigned k) {
  if (kept.size() <= k) kept.resize(k + 1);
  if (!kept[k]) kept[k] = make_piece_writer<Writer>();
  return kept[k];
}

}  // namespace

struct PieceWriters::Kept {
  std::vector<vtkSmartPointer<StreamWriter<vtkXMLUnstructuredGridWriter>>> grids;
  std::vector<vtkSmartPointer<StreamWriter<vtkXMLPolyDataWriter>>> polys;
};

PieceWriters::PieceWriters() : kept_(std::make_unique<Kept>()) {}
PieceWriters::~PieceWriters() = default;

void PieceWriters::write(unsigned k, vtkDataObject* block, vtkDataCompressor* compressor,
                         const std::string& name, std::string& buffer) {
  if (piece_.write(block, compressor, buffer)) return;
  ++by_vtk_;
  if (vtkUnstructuredGrid::SafeDownCast(block) != nullptr)
    piece_bytes(kept_at(kept_->grids, k), block, compressor, name, buffer);
  else
    piece_bytes(kept_at(kept_->polys, k), block, compressor, name, buffer);
}

}  // namespace mrsim
