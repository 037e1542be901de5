#pragma once
// A tetrahedral mesh as loaded from disk: rest positions in metres and positively oriented
// tets (det[X1-X0, X2-X0, X3-X0] > 0). Every consumer relies on both properties.
#include <array>
#include <vector>

#include "core/vec.hpp"

namespace mrsim {

using Tet = std::array<int, 4>;

struct TetMesh {
  std::vector<Vec3> points;
  std::vector<Tet> tets;
};

/// Signed volume of a tet: positive when the vertices are ordered as mrsim expects.
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Length of the diagonal of the points' axis-aligned bounding box (m); the mesh has points.
double bbox_diagonal(const TetMesh& mesh);

}  // namespace mrsim
