#include "meshing/surface_checks.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.hpp"
#include "meshing/self_intersection.hpp"
#include "meshing/surface_topology.hpp"

namespace mrsim {
namespace {

void check_finite(const SurfaceMesh& surface, const std::string& name) {
  for (std::size_t i = 0; i < surface.points.size(); ++i) {
    if (!surface.points[i].allFinite()) {
      throw InputError(name + ": vertex " + std::to_string(i + 1) + " (1-based, in file order) has a "
                       "non-finite coordinate " + describe_point(surface.points[i]));
    }
  }
}

double triangle_aspect(const SurfaceMesh& s, const Triangle& t) {
  const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  if (longest == 0.0) return 0.0;
  return (b - a).cross(c - a).norm() / longest;
}

void check_no_degenerate_triangles(const SurfaceMesh& surface, const std::string& name) {
  int degenerate = 0, first = -1;
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t) {
    if (triangle_aspect(surface, surface.triangles[t]) < kMinTriangleAspect && degenerate++ == 0) first = t;
  }
  if (degenerate == 0) return;
  const Triangle& t = surface.triangles[first];
  throw InputError(name + ": " + std::to_string(degenerate) + " zero-area triangle" +
                   (degenerate > 1 ? "s" : "") + " (collinear or repeated corners), e.g. from " +
                   surface.face_noun + " " + std::to_string(surface.face_of[first]) + " with corners " +
                   describe_point(surface.points[t[0]]) + ", " + describe_point(surface.points[t[1]]) +
                   ", " + describe_point(surface.points[t[2]]) +
                   "; a polygon face must be convex and planar, without collinear corners");
}

void check_no_self_intersection(const SurfaceMesh& surface, const std::string& name) {
  const SelfIntersections found = find_self_intersections(surface);
  if (found.pairs == 0) return;
  const auto [i, j] = found.first.front();
  throw InputError(name + ": self-intersecting surface: " + std::to_string(found.pairs) +
                   " pairs of triangles cross or touch, e.g. " + surface.face_noun + "s " +
                   std::to_string(surface.face_of[i]) + " and " + std::to_string(surface.face_of[j]) +
                   " near " + describe_point(surface.points[surface.triangles[i][0]]));
}

void check_single_body(const SurfaceMesh& surface, const std::string& name) {
  const int parts = connected_components(surface);
  if (parts > 1) {
    throw InputError(name + ": the surface has " + std::to_string(parts) +
                     " separate closed parts; mrsim mesh builds one body (mesh each part "
                     "separately, or join them)");
  }
}

}  // namespace

SurfaceCheckReport check_surface(SurfaceMesh& surface, const std::string& name) {
  SurfaceCheckReport report;
  check_finite(surface, name);
  report.merged_points = weld_identical_points(surface);
  check_no_degenerate_triangles(surface, name);
  check_edges_closed(surface, name);
  check_vertex_fans(surface, name);
  report.flipped_triangles = orient_consistently(surface, name);
  double volume = enclosed_volume(surface);
  if (volume < 0.0) {
    for (Triangle& t : surface.triangles) std::swap(t[1], t[2]);
    report.flipped_triangles = static_cast<int>(surface.triangles.size()) - report.flipped_triangles;
    volume = -volume;
  }
  check_no_self_intersection(surface, name);
  check_single_body(surface, name);
  report.genus = surface_genus(surface);
  report.enclosed_volume = volume;
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t) report.area += triangle_area(surface, t);
  return report;
}

}  // namespace mrsim
