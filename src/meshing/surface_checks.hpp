#pragma once
// Everything a surface must satisfy before mrsim tetrahedralises it, checked in this order so
// that each defect gets its own message (and exit code 2 from the command):
//  1. finite coordinates;  2. no zero-area (degenerate) triangles, e.g. from fan-triangulated
//  polygons;  3. closed and edge-manifold;  4. no pinched vertex;  5. orientable (orientation
//  repaired, then turned outward);  6. no self-intersection;  7. one connected body.
#include <string>

#include "meshing/surface_mesh.hpp"

namespace mrsim {

struct SurfaceCheckReport {
  int merged_points = 0;      // identical points welded (STL facets, duplicated vertices)
  int flipped_triangles = 0;  // triangles re-oriented for consistency or to face outward
  int genus = 0;
  double enclosed_volume = 0.0;  // in the surface's units, > 0 after the checks
  double area = 0.0;
};

/// Relative area below which a triangle counts as degenerate: 2 * area / (longest edge)^2,
/// i.e. its height relative to its longest edge. Scale-free.
inline constexpr double kMinTriangleAspect = 1e-8;

/// Checks `surface` (welds identical points and orients it outward in place). Throws
/// InputError naming `name` and the reason for the first failed check.
SurfaceCheckReport check_surface(SurfaceMesh& surface, const std::string& name);

}  // namespace mrsim
