#pragma once
// Improves the triangle shapes of a simplified surface before gmsh fills it with tets (a
// badly shaped boundary triangle forces a badly shaped tet, since gmsh keeps the surface):
// rounds of Delaunay edge flips where the two diagonals nearly meet (the flip barely changes
// the shape), and of tangential smoothing (each vertex moved towards the centroid of
// its neighbours within its tangent plane, if that raises the worst quality around it).
// Every edit passes EditableSurface's checks, so topology and the absence of
// self-intersections are kept. Deterministic (vertices and edges in index order).
#include "meshing/surface_mesh.hpp"

namespace mrsim {

struct ImproveOptions {
  int rounds = 6;
  double max_flip_gap = 0.1;  // flip where the diagonals pass closer than this x the shorter
  double max_move_turn_deg = 20.0;  // a smoothing move may turn a triangle this much
};

SurfaceMesh improve_triangle_shapes(const SurfaceMesh& surface, const ImproveOptions& options = {});

}  // namespace mrsim
