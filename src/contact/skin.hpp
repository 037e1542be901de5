#pragma once
// The object's skin (method.md §6.2 point 1): the triangle surface the tools touch and the
// `surface` block shows. Either the boundary of the finest level or a separate, finer surface
// given in the scenario; every vertex is then bound to a tet of every level (skin_binding.hpp).
#include <array>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

struct Skin {
  std::vector<Vec3> rest;                      // m
  std::vector<std::array<int, 3>> triangles;   // outward-oriented
  std::vector<double> area;                    // m², a third of each adjacent triangle
  std::vector<double> edge;                    // m, mean length of the edges at each vertex
  std::vector<int> point;  // a boundary skin: the mesh point each vertex is (empty: a given surface)
};

/// The boundary faces of `mesh`, its boundary vertices renumbered in increasing order.
Skin boundary_skin(const TetMesh& mesh);

/// A given surface (points in m); vertices no triangle uses are kept with area 0.
Skin surface_skin(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles);

}  // namespace mrsim
