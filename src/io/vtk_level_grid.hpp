#pragma once
// One level of one frame as a vtkUnstructuredGrid: points at the deformed positions X + u,
// VTK_TETRA cells, and the point arrays of docs/output.md. Internal to mrsim_io (VTK types
// stay out of the public headers).
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <vector>

#include "io/frame_data.hpp"

namespace mrsim {

/// Builds the grid of a level; `view` must have passed check_level_view. `time` (s) is stored
/// as the field array TimeValue so that a single .vtu opened alone still knows its time.
vtkSmartPointer<vtkUnstructuredGrid> make_level_grid(const LevelFrameView& view, double time);

/// The level grids of a series, kept from frame to frame: a level's cells (connectivity, offsets,
/// types) are built at its first frame, and VTK's list of the grid's distinct cell types, which
/// the XML writer asks for, stays valid; later frames refill points and arrays only. The same
/// grids as make_level_grid's, written to the same bytes.
class LevelGrids {
 public:
  /// The grid of block `level` for this frame: a new one when the view's mesh is another object
  /// (or has other sizes) than the last frame's. A mesh must not change in place during a
  /// series (a run's meshes are constant).
  vtkUnstructuredGrid* update(std::size_t level, const LevelFrameView& view, double time);

 private:
  struct Kept {
    const TetMesh* mesh = nullptr;
    std::size_t points = 0, tets = 0;
    vtkSmartPointer<vtkUnstructuredGrid> grid;
  };
  std::vector<Kept> kept_;
};

}  // namespace mrsim
