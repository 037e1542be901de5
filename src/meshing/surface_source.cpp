#include "meshing/surface_source.hpp"

#include <gmsh.h>

#include <cmath>
#include <numbers>

#include "meshing/gmsh_session.hpp"

namespace mrsim {

SurfaceSource::SurfaceSource(SurfaceMesh surface, double enclosed_volume, std::string name,
                             double feature_angle_deg)
    : surface_(std::move(surface)), volume_(enclosed_volume), name_(std::move(name)),
      feature_angle_deg_(feature_angle_deg) {}

void SurfaceSource::build(GmshModel& model) const {
  const int surface_tag = gmsh::model::addDiscreteEntity(2);
  std::vector<std::size_t> node_tags(surface_.points.size());
  std::vector<double> coords;
  coords.reserve(3 * surface_.points.size());
  for (std::size_t i = 0; i < surface_.points.size(); ++i) {
    node_tags[i] = i + 1;
    coords.insert(coords.end(), {surface_.points[i].x(), surface_.points[i].y(), surface_.points[i].z()});
  }
  gmsh::model::mesh::addNodes(2, surface_tag, node_tags, coords);
  std::vector<std::size_t> corners;
  corners.reserve(3 * surface_.triangles.size());
  for (const Triangle& t : surface_.triangles) {
    for (int v : t) corners.push_back(static_cast<std::size_t>(v) + 1);
  }
  constexpr int kTriangle = 2;  // gmsh element type of a 3-node triangle
  gmsh::model::mesh::addElementsByType(surface_tag, kTriangle, {}, corners);
  const double angle = feature_angle_deg_ * std::numbers::pi / 180.0;
  // forReparametrization: patches gmsh can map to the plane, which its 2-D mesher needs.
  gmsh::model::mesh::classifySurfaces(angle, true, true, std::numbers::pi);
  gmsh::model::mesh::createGeometry();
  model.throw_on_errors("cannot build a geometry from the surface of " + name_);
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<int> tags;
  for (const auto& [dim, tag] : surfaces) tags.push_back(tag);
  const int loop = gmsh::model::geo::addSurfaceLoop(tags);
  gmsh::model::geo::addVolume({loop});
  gmsh::model::geo::synchronize();
  model.throw_on_errors("cannot build a volume inside the surface of " + name_);
}

}  // namespace mrsim
