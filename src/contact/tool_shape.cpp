#include "contact/tool_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mrsim {

namespace {

// Below this length a direction is meaningless (and its square may underflow): fall back.
constexpr double kTinyLength = 1e-150;

Vec3 unit_or(const Vec3& v, const Vec3& fallback) {
  const double n = v.norm();
  return n > kTinyLength ? Vec3(v / n) : fallback;
}

// Sphere and capsule are a ball of radius r around a segment: one formula for inside and
// outside. At the segment itself the direction is undefined; -z at the tip (the working
// direction) and +x along the shaft keep the result deterministic.
ShapeProbe probe_swept_ball(const Vec3& p, double radius, double length) {
  const Vec3 nearest(0, 0, std::clamp(p.z(), 0.0, length));
  const Vec3 d = p - nearest;
  const bool shaft = nearest.z() > 0 && nearest.z() < length;
  const Vec3 fallback = shaft ? Vec3::UnitX() : Vec3(-Vec3::UnitZ());
  return {radius - d.norm(), unit_or(d, fallback)};
}

// Inside the punch: the closest of the flat face, the top face and the side (ties go to the
// working face first so the choice is deterministic).
ShapeProbe probe_punch_inside(const Vec3& p, double radius, double length, double rho) {
  ShapeProbe best{p.z(), -Vec3::UnitZ()};
  if (length - p.z() < best.depth) best = {length - p.z(), Vec3::UnitZ()};
  if (radius - rho < best.depth)
    best = {radius - rho, unit_or(Vec3(p.x(), p.y(), 0), Vec3::UnitX())};
  return best;
}

// Outside the punch: exact distance to the solid cylinder through its nearest point.
ShapeProbe probe_punch_outside(const Vec3& p, double radius, double length, double rho) {
  const double scale = rho > radius ? radius / rho : 1.0;
  const Vec3 nearest(p.x() * scale, p.y() * scale, std::clamp(p.z(), 0.0, length));
  const Vec3 d = p - nearest;
  return {-d.norm(), unit_or(d, -Vec3::UnitZ())};
}

ShapeProbe probe_punch(const Vec3& p, double radius, double length) {
  const double rho = std::hypot(p.x(), p.y());
  const bool inside = rho <= radius && p.z() >= 0 && p.z() <= length;
  return inside ? probe_punch_inside(p, radius, length, rho)
                : probe_punch_outside(p, radius, length, rho);
}

}  // namespace

ShapeProbe probe(const ToolShape& shape, const Vec3& p) {
  switch (shape.kind) {
    case ToolShapeKind::Sphere:
      return probe_swept_ball(p, shape.radius, 0.0);
    case ToolShapeKind::Capsule:
      return probe_swept_ball(p, shape.radius, shape.length);
    case ToolShapeKind::FlatCylinder:
      return probe_punch(p, shape.radius, shape.length);
  }
  return {};
}

double bounding_radius(const ToolShape& shape) {
  switch (shape.kind) {
    case ToolShapeKind::Sphere:
      return shape.radius;
    case ToolShapeKind::Capsule:
      return shape.length + shape.radius;
    case ToolShapeKind::FlatCylinder:
      return std::hypot(shape.radius, shape.length);
  }
  return 0;
}

double contact_area(const ToolShape& shape) {
  const double r = shape.radius, pi = std::numbers::pi;
  switch (shape.kind) {
    case ToolShapeKind::Sphere:
      return 2 * pi * r * r;
    case ToolShapeKind::Capsule:
      return 2 * pi * r * r + pi * r * shape.length;
    case ToolShapeKind::FlatCylinder:
      return pi * r * r + pi * r * shape.length;
  }
  return 0;
}

std::string shape_name(ToolShapeKind kind) {
  switch (kind) {
    case ToolShapeKind::Sphere:
      return "sphere";
    case ToolShapeKind::Capsule:
      return "capsule";
    case ToolShapeKind::FlatCylinder:
      return "flat_cylinder";
  }
  return "unknown";
}

}  // namespace mrsim
