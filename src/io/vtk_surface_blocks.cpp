#include "io/vtk_surface_blocks.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSignedCharArray.h>

#include <array>
#include <cstdint>
#include <vector>

#include "io/vtk_arrays.hpp"
#include "io/vtk_tetra_cells.hpp"

namespace mrsim {
namespace {

using Triangle = std::array<int, 3>;

// Triangles, each piece's corners shifted by the number of points before it in the block.
struct TrianglePiece {
  std::span<const Triangle> triangles;
  vtkIdType first_point = 0;
};

vtkSmartPointer<vtkCellArray> triangle_cells(std::span<const TrianglePiece> pieces,
                                             vtkIdType points) {
  std::vector<std::array<vtkIdType, 3>> corners;
  for (const TrianglePiece& piece : pieces)
    for (const Triangle& t : piece.triangles)
      corners.push_back({piece.first_point + t[0], piece.first_point + t[1],
                         piece.first_point + t[2]});
  return uniform_cells<3>(static_cast<vtkIdType>(corners.size()), points,
                          [&](vtkIdType c, int k) { return corners[c][k]; });
}

void add_surface_arrays(vtkPointData* data, const SurfaceFrameView& surface) {
  data->AddArray(vector_array("displacement", surface.displacement));
  data->AddArray(vector_array("velocity", surface.velocity));
  data->AddArray(vector_array("contact_force", surface.contact_force));
  data->AddArray(scalar_array<vtkSignedCharArray>("level", surface.level));  // Int8 in XML
  // Same default vector as the level blocks, so one glyph setting fits every block.
  data->SetActiveVectors("displacement");
}

vtkIdType total_points(std::span<const ToolFrameView> tools) {
  std::size_t n = 0;
  for (const ToolFrameView& tool : tools) n += tool.points.size();
  return static_cast<vtkIdType>(n);
}

vtkIdType total_triangles(std::span<const ToolFrameView> tools) {
  std::size_t n = 0;
  for (const ToolFrameView& tool : tools) n += tool.triangles.size();
  return static_cast<vtkIdType>(n);
}

// All tools' points, in tool order: tool k's points start after those of tools 0..k-1.
vtkSmartPointer<vtkPoints> tool_points(std::span<const ToolFrameView> tools) {
  auto points = double_points(total_points(tools));
  vtkIdType next = 0;
  for (const ToolFrameView& tool : tools) {
    for (const Vec3& p : tool.points) points->SetPoint(next++, p.x(), p.y(), p.z());
  }
  return points;
}

vtkSmartPointer<vtkCellArray> tool_triangles(std::span<const ToolFrameView> tools) {
  std::vector<TrianglePiece> pieces;
  vtkIdType first_point = 0;
  for (const ToolFrameView& tool : tools) {
    pieces.push_back({tool.triangles, first_point});
    first_point += static_cast<vtkIdType>(tool.points.size());
  }
  return triangle_cells(pieces, first_point);
}

// Cell array `tool`: which tool each triangle belongs to (to colour or threshold by tool).
vtkSmartPointer<vtkIntArray> tool_index_array(std::span<const ToolFrameView> tools) {
  std::vector<std::int32_t> index;
  index.reserve(static_cast<std::size_t>(total_triangles(tools)));
  for (std::size_t k = 0; k < tools.size(); ++k) {
    index.insert(index.end(), tools[k].triangles.size(), static_cast<std::int32_t>(k));
  }
  return scalar_array<vtkIntArray>("tool", std::span<const std::int32_t>(index));
}

vtkSmartPointer<vtkDoubleArray> tool_force_array(std::span<const ToolFrameView> tools) {
  std::vector<Vec3> force;
  force.reserve(tools.size());
  for (const ToolFrameView& tool : tools) force.push_back(tool.force);
  return vector_array("force", force);
}

}  // namespace

vtkSmartPointer<vtkPolyData> make_surface_block(const SurfaceFrameView& surface, double time) {
  auto block = vtkSmartPointer<vtkPolyData>::New();
  block->SetPoints(deformed_points(surface.rest, surface.displacement));
  const TrianglePiece piece{surface.triangles, 0};
  block->SetPolys(triangle_cells({&piece, 1}, static_cast<vtkIdType>(surface.rest.size())));
  add_surface_arrays(block->GetPointData(), surface);
  add_time_value(block->GetFieldData(), time);
  return block;
}

vtkSmartPointer<vtkPolyData> make_tool_block(std::span<const ToolFrameView> tools, double time) {
  auto block = vtkSmartPointer<vtkPolyData>::New();
  block->SetPoints(tool_points(tools));
  block->SetPolys(tool_triangles(tools));
  block->GetCellData()->AddArray(tool_index_array(tools));
  // Per tool, not per point or cell: one force per rigid body, as in /frames/tool_force.
  block->GetFieldData()->AddArray(tool_force_array(tools));
  add_time_value(block->GetFieldData(), time);
  return block;
}

}  // namespace mrsim
