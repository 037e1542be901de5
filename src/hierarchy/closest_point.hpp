#pragma once
// Closest point of a triangle to a point (Voronoi-region classification of the query against
// the triangle's vertices, edges and face).
#include "core/vec.hpp"

namespace mrsim {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace mrsim
