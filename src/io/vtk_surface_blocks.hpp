#pragma once
// The `surface` and `tool` blocks of a frame (docs/output.md) as vtkPolyData of triangles,
// written as .vtp pieces next to the level grids. Internal to mrsim_io.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <span>

#include "io/frame_data.hpp"

namespace mrsim {

/// The object's skin at the deformed positions rest + displacement, with the point arrays
/// displacement, velocity, contact_force, level and the field array TimeValue (s).
/// `surface` must have passed check_surface_view.
vtkSmartPointer<vtkPolyData> make_surface_block(const SurfaceFrameView& surface, double time);

/// Every tool's triangles in one polydata (points concatenated in tool order), the cell array
/// `tool` (index of each triangle's tool) and the field arrays `force` (one tuple per tool)
/// and TimeValue. Each tool must have passed check_tool_view.
vtkSmartPointer<vtkPolyData> make_tool_block(std::span<const ToolFrameView> tools, double time);

}  // namespace mrsim
