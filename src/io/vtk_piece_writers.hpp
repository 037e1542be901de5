#pragma once
// The bytes of a frame's blocks (one .vtu or .vtp each): written by VtkXmlPiece (VTK's bytes
// without VTK's pipeline, io/vtk_xml_piece.hpp), or, for a block holding what only VTK writes
// exactly, by VTK's own XML writer for its position in the frame, kept from frame to frame (a
// writer and its pipeline executive made for every piece cost a fifth of VTK's time).
#include <cstddef>
#include <memory>
#include <string>

#include "io/vtk_xml_piece.hpp"

class vtkDataCompressor;
class vtkDataObject;

namespace mrsim {

class PieceWriters {
 public:
  PieceWriters();
  ~PieceWriters();
  PieceWriters(const PieceWriters&) = delete;
  PieceWriters& operator=(const PieceWriters&) = delete;

  /// Replaces `buffer` with the file of `block` (a vtkUnstructuredGrid or vtkPolyData), the
  /// `k`-th of its frame, its data compressed by `compressor` (nullptr: raw). Throws RunError
  /// naming `name` (the piece's file) when VTK's writer fails.
  void write(unsigned k, vtkDataObject* block, vtkDataCompressor* compressor,
             const std::string& name, std::string& buffer);
  /// Pieces written by VTK's writer (none in the frames mrsim makes: tests check it).
  std::size_t written_by_vtk() const { return by_vtk_; }

 private:
  struct Kept;  // VTK's writers, by block position
  VtkXmlPiece piece_;
  std::unique_ptr<Kept> kept_;
  std::size_t by_vtk_ = 0;
};

}  // namespace mrsim
