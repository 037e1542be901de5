#pragma once
// A checked, outward-oriented surface (metres) handed to gmsh as a discrete surface. gmsh
// splits it into patches it can parametrise (classifySurfaces), builds a geometry on them
// (createGeometry) and remeshes that geometry at the requested size: this remeshing is what
// coarsens a detailed surface for the coarse levels, where the thesis used qslim.
#include <memory>

#include "meshing/geometry_source.hpp"
#include "meshing/simplified_surface_source.hpp"
#include "meshing/surface_mesh.hpp"

namespace mrsim {

class SurfaceSource : public GeometrySource {
 public:
  /// `feature_angle_deg`: edges sharper than this stay sharp (patch boundaries); 180 treats
  /// the surface as smooth everywhere.
  SurfaceSource(SurfaceMesh surface, double enclosed_volume, std::string name,
                double feature_angle_deg = 180.0);
  void build(GmshModel& model, double size) const override;
  double volume() const override { return volume_; }
  std::string name() const override { return name_; }
  /// The same surface, simplified and kept instead of remeshed (simplified_surface_source.hpp).
  const GeometrySource* fallback() const override { return &fallback_; }

 private:
  SurfaceMesh surface_;
  double volume_;
  std::string name_;
  double feature_angle_deg_;
  SimplifiedSurfaceSource fallback_;
};

}  // namespace mrsim
