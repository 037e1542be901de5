#include "meshing/surface_source.hpp"

#include <gmsh.h>

#include <cmath>
#include <numbers>

#include "meshing/discrete_surface.hpp"
#include "meshing/gmsh_session.hpp"

namespace mrsim {

SurfaceSource::SurfaceSource(SurfaceMesh surface, double enclosed_volume, std::string name,
                             double feature_angle_deg)
    : surface_(std::move(surface)), volume_(enclosed_volume), name_(std::move(name)),
      feature_angle_deg_(feature_angle_deg), fallback_(surface_, volume_, name_) {}

void SurfaceSource::build(GmshModel& model, double /*size*/) const {
  add_discrete_surface(surface_);
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
