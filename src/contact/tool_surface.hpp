#pragma once
// A triangulated picture of a tool shape, in the tool frame, for the VTU `tool` block.
#include <array>
#include <vector>

#include "contact/tool_shape.hpp"

namespace mrsim {

struct TriangleSurface {
  std::vector<Vec3> points;
  // Outward-oriented: counter-clockwise seen from outside.
  std::vector<std::array<int, 3>> triangles;
};

/// Closed, outward-oriented, about `segments` facets around the axis (>= 8).
TriangleSurface tool_surface(const ToolShape& shape, int segments = 24);

}  // namespace mrsim
