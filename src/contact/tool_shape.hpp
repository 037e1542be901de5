#pragma once
// The rigid shapes a tool can have (scenario `tools[].shape`), in the tool's own frame: the
// axis is +z, the working end at the origin, the handle towards +z. With the identity
// orientation a tool therefore presses downwards (-z) onto a body below it.
//   sphere:         centre at the origin, radius r.
//   capsule:        a probe with a rounded tip: the segment from the origin to (0, 0, length)
//                   swept by a ball of radius r (tip sphere centred at the origin).
//   flat_cylinder:  a punch: the disc of radius r in the plane z = 0 is its flat face, the
//                   solid cylinder extends to z = length.
#include <string>

#include "core/vec.hpp"

namespace mrsim {

enum class ToolShapeKind { Sphere, Capsule, FlatCylinder };

struct ToolShape {
  ToolShapeKind kind = ToolShapeKind::Sphere;
  double radius = 0;  // m
  double length = 0;  // m, capsule axis segment / punch height (unused for a sphere)
};

/// Where a point lies against the shape: depth > 0 inside (how far it must move along
/// `normal`, the outward unit normal of the nearest face, to reach the surface), depth <= 0
/// outside (minus the exact distance to the solid; `normal` then points from its nearest
/// point, on a face or on the punch's rim, towards p).
struct ShapeProbe {
  double depth = 0;
  Vec3 normal = Vec3::UnitZ();
};

/// `p` in the tool frame. Never NaN: on the axis or at the centre a fixed normal is chosen.
ShapeProbe probe(const ToolShape& shape, const Vec3& p);

/// Radius of a ball centred at the origin of the tool frame that contains the shape.
double bounding_radius(const ToolShape& shape);

/// The largest skin area the tool can press at once (m²): half its surface (a body does not
/// wrap more of a tool than the side that faces it). Bounds the contact stiffness a point can
/// receive (contact/contact_bound.hpp).
double contact_area(const ToolShape& shape);

/// "sphere", "capsule", "flat_cylinder" (the schema's keys).
std::string shape_name(ToolShapeKind kind);

}  // namespace mrsim
