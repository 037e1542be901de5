#pragma once
// One block of a frame as a VTK XML file (.vtu for an UnstructuredGrid, .vtp for a PolyData) in
// the one form mrsim writes: appended raw binary, UInt64 headers, data in VTK's blocks of 32 KiB
// compressed by the series' compressor (or not). The bytes are those vtkXMLUnstructuredGridWriter
// and vtkXMLPolyDataWriter write with these settings (VtkCompression.
// FramesAreTheBytesOfVtksMultiblockWriter), without their pipeline: VTK's writers spent 34 % of
// liver_thesis' instructions on its frames (executives, information objects, the stream's
// formatting, a reserved-then-patched header, a range pass over every array), more than its
// simulation (callgrind, docs/performance.md).
//
// What this writer does not know how to write exactly as VTK does (an array that is empty,
// unnamed, holds a NaN or an infinity, carries information keys, of vtkIdType or of a layout
// other than an array of structures; polyhedra) it leaves to VTK's writer: write() returns false.
#include <cstddef>
#include <string>
#include <vector>

class vtkDataCompressor;
class vtkDataObject;

namespace mrsim {

class VtkXmlPiece {
 public:
  /// Replaces `out` with the file of `block` (a vtkUnstructuredGrid or vtkPolyData), its data
  /// compressed by `compressor` (nullptr: raw). Returns false, `out` unspecified, when the block
  /// holds what only VTK's own writer writes (see above); nothing was compressed then.
  bool write(vtkDataObject* block, vtkDataCompressor* compressor, std::string& out);

 private:
  void append(const unsigned char* bytes, std::size_t size, vtkDataCompressor* compressor);
  std::string data_;                  // the appended data, built before the header that indexes it
  std::vector<unsigned char> packed_;  // one compressed block
};

}  // namespace mrsim
