#pragma once
// Geometric tests behind the self-intersection check: does a segment meet a triangle, do two
// triangles meet. Closed tests (touching counts as meeting: a surface that touches itself
// cannot bound a tetrahedral mesh either). Signs come from plain double determinants: enough
// to flag real defects, which cross by far more than round-off.
#include <array>

#include "core/vec.hpp"

namespace mrsim {

using TriangleCorners = std::array<Vec3, 3>;

/// True when the closed segment [p, q] and the closed triangle t have a common point.
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const TriangleCorners& t);

/// True when two triangles with no common vertex have a common point.
bool disjoint_triangles_meet(const TriangleCorners& a, const TriangleCorners& b);

/// Two triangles sharing exactly one vertex: `a[0] == b[0]` is the shared corner. True when
/// they meet anywhere else than along that corner (one folds through the other).
bool corner_sharing_triangles_overlap(const TriangleCorners& a, const TriangleCorners& b);

}  // namespace mrsim
