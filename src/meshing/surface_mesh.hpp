#pragma once
// A closed triangulated surface as read from STL, OBJ, OFF or PLY: the input of `mrsim mesh`.
// Points are in the file's units until scaled; triangles index `points`. `face_of` keeps, for
// each triangle, the 1-based face number of the file it came from (a polygon gives several
// triangles), so that every error names the face the user can find in their own tools.
#include <array>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace mrsim {

using Triangle = std::array<int, 3>;

struct SurfaceMesh {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::vector<int> face_of;  // same size as triangles: 1-based face number in the file
  std::string face_noun = "face";  // "facet" for STL
};

/// Signed volume enclosed by the surface (divergence theorem): positive when the triangles
/// are oriented outward. Meaningful only for a closed surface.
double enclosed_volume(const SurfaceMesh& surface);

/// Area of one triangle of the surface.
double triangle_area(const SurfaceMesh& surface, int triangle);

/// Multiplies every coordinate by `factor` (unit conversion).
void scale_surface(SurfaceMesh& surface, double factor);

/// Merges points with bit-identical coordinates (STL repeats every vertex per facet) and
/// drops points no triangle uses. Keeps the order of first use, so the result is
/// deterministic. Returns how many points were merged.
int weld_identical_points(SurfaceMesh& surface);

}  // namespace mrsim
