#pragma once
// Coarsens a closed, oriented, self-intersection-free triangulated surface by edge collapses,
// the role qslim played before GHS3D in the thesis. Collapses are ordered by the quadric error
// of the merged point (how far it lies from the input triangles it replaces) plus a length
// term, so short edges go first and the result is near-uniform, as a tet mesh of one size
// wants; the merged point is moved along the normal so that the enclosed volume stays exactly
// the same (coarse surfaces would otherwise be inscribed and shrink). Unlike gmsh's remeshing
// it cannot break a surface with narrow tunnels: a collapse is made only if
//  - the link condition holds (the genus stays, the surface stays a 2-manifold),
//  - no triangle flips, turns by more than `max_normal_turn_deg` or gets worse shaped than
//    `min_triangle_quality` (unless no worse than the worst triangle it replaces),
//  - no two edge neighbours fold onto each other,
//  - none of its new triangles meets another triangle (self_intersection.hpp's exact test).
// (the checks of editable_surface.hpp). Deterministic: ties are broken by vertex numbers.
#include <cstddef>

#include "meshing/surface_mesh.hpp"

namespace mrsim {

struct SimplifyOptions {
  std::size_t target_triangles = 0;   // stop when this many are left (or nothing can collapse)
  double length_weight = 0.1;         // cost = mean squared distance + w * (edge length)^2 ...
  double shape_weight = 0.5;          // ... + w * (1 - worst new triangle quality) * length^2
  double min_triangle_quality = 0.2;  // 4 sqrt(3) area / sum of squared edges: 1 equilateral
  double max_normal_turn_deg = 60.0;
};

struct SimplifiedSurface {
  SurfaceMesh surface;          // points renumbered in order of first use, face_of = 1..n
  std::size_t collapses = 0;
  bool reached_target = false;  // false: every remaining collapse was refused
};

SimplifiedSurface simplify_surface(const SurfaceMesh& surface, const SimplifyOptions& options);

}  // namespace mrsim
