#pragma once
// One level of one frame as a vtkUnstructuredGrid: points at the deformed positions X + u,
// VTK_TETRA cells, and the point arrays of docs/output.md. Internal to mrsim_io (VTK types
// stay out of the public headers).
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include "io/frame_data.hpp"

namespace mrsim {

/// Builds the grid of a level; `view` must have passed check_level_view. `time` (s) is stored
/// as the field array TimeValue so that a single .vtu opened alone still knows its time.
vtkSmartPointer<vtkUnstructuredGrid> make_level_grid(const LevelFrameView& view, double time);

}  // namespace mrsim
