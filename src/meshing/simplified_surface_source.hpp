#pragma once
// The fallback for surfaces gmsh cannot remesh at the requested sizes (the genus-2 femur,
// whose tunnels are narrower than coarse elements; docs/meshing.md): the surface is first
// coarsened by topology-preserving edge collapses (surface_simplifier.hpp, qslim's role in
// the thesis) to about as many triangles as a uniform mesh of the target size has on its
// boundary, then handed to gmsh as a discrete surface that gmsh keeps as it is and only fills
// with tets (3-D Delaunay and gmsh's optimiser, the size field capped at the target size).
#include "meshing/geometry_source.hpp"
#include "meshing/surface_mesh.hpp"

namespace mrsim {

class SimplifiedSurfaceSource : public GeometrySource {
 public:
  SimplifiedSurfaceSource(SurfaceMesh surface, double enclosed_volume, std::string name);
  void build(GmshModel& model, double size) const override;
  double volume() const override { return volume_; }
  std::string name() const override { return name_; }

  /// Boundary triangles asked of the simplifier for a target edge length (m): the count of
  /// equilateral triangles of that edge covering the surface's area.
  std::size_t target_triangles(double size) const;

  /// The surface build() hands to gmsh for `size`.
  SurfaceMesh simplified(double size) const;

 private:
  SurfaceMesh surface_;
  double volume_;
  std::string name_;
  double area_ = 0.0;
};

}  // namespace mrsim
