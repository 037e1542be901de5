#include "meshing/discrete_surface.hpp"

#include <gmsh.h>

namespace mrsim {

int add_discrete_surface(const SurfaceMesh& surface) {
  const int surface_tag = gmsh::model::addDiscreteEntity(2);
  std::vector<std::size_t> node_tags(surface.points.size());
  std::vector<double> coords;
  coords.reserve(3 * surface.points.size());
  for (std::size_t i = 0; i < surface.points.size(); ++i) {
    node_tags[i] = i + 1;
    coords.insert(coords.end(), {surface.points[i].x(), surface.points[i].y(), surface.points[i].z()});
  }
  gmsh::model::mesh::addNodes(2, surface_tag, node_tags, coords);
  std::vector<std::size_t> corners;
  corners.reserve(3 * surface.triangles.size());
  for (const Triangle& t : surface.triangles) {
    for (int v : t) corners.push_back(static_cast<std::size_t>(v) + 1);
  }
  constexpr int kTriangle = 2;  // gmsh element type of a 3-node triangle
  gmsh::model::mesh::addElementsByType(surface_tag, kTriangle, {}, corners);
  return surface_tag;
}

}  // namespace mrsim
