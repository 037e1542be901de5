#pragma once
// Finds pairs of triangles of a surface that cross or touch each other although they are not
// neighbours (parts intersecting each other, folds). A uniform grid over the bounding boxes
// limits the exact tests to nearby pairs, so the check is near-linear in the triangle count.
#include <utility>
#include <vector>

#include "meshing/surface_mesh.hpp"

namespace mrsim {

struct SelfIntersections {
  std::size_t pairs = 0;                  // how many intersecting pairs
  std::vector<std::pair<int, int>> first; // up to a few examples (triangle indices, i < j)
};

SelfIntersections find_self_intersections(const SurfaceMesh& surface);

/// The exact test behind find_self_intersections, for two triangles of one surface: true when
/// they meet anywhere else than along the vertices they share. Edge neighbours (two shared
/// vertices) never count: folds across an edge are the orientation's business.
bool triangles_meet(const std::vector<Vec3>& points, const Triangle& a, const Triangle& b);

}  // namespace mrsim
