#pragma once
// What `mrsim mesh` tetrahedralises: a checked surface read from a file, or a built-in shape.
// Each attempt of the size search rebuilds the solid in a fresh gmsh model (cheap next to
// the volume meshing), so attempts cannot influence each other.
#include <string>

namespace mrsim {

class GmshModel;

class GeometrySource {
 public:
  virtual ~GeometrySource() = default;
  /// Builds the solid, as one gmsh volume, into the current model, for a mesh of target edge
  /// length `size` (m; only sources that prepare their own surface use it). Throws GmshFailure.
  virtual void build(GmshModel& model, double size) const = 0;
  /// Volume enclosed by the input (m^3): the reference of the volume error of each level.
  virtual double volume() const = 0;
  /// For messages: "liver.off" or "shape sphere(r=0.05)".
  virtual std::string name() const = 0;
  /// What to mesh instead when gmsh cannot mesh this source at any size near a target, or
  /// null. The size search uses it only then, so inputs that mesh keep their meshes.
  virtual const GeometrySource* fallback() const { return nullptr; }
};

}  // namespace mrsim
