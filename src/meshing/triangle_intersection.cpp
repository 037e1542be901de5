#include "meshing/triangle_intersection.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace mrsim {
namespace {

double orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a));
}

int sign(double x) { return (x > 0.0) - (x < 0.0); }

// --- coplanar case: 2-D tests after dropping the dominant axis of the triangle's normal ---

using Vec2 = Eigen::Vector2d;

double orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool on_segment_2d(const Vec2& p, const Vec2& a, const Vec2& b) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

bool segments_meet_2d(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  const int o1 = sign(orient2d(p, q, a)), o2 = sign(orient2d(p, q, b));
  const int o3 = sign(orient2d(a, b, p)), o4 = sign(orient2d(a, b, q));
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment_2d(a, p, q)) || (o2 == 0 && on_segment_2d(b, p, q)) ||
         (o3 == 0 && on_segment_2d(p, a, b)) || (o4 == 0 && on_segment_2d(q, a, b));
}

bool inside_triangle_2d(const Vec2& p, const std::array<Vec2, 3>& t) {
  const int s0 = sign(orient2d(t[0], t[1], p)), s1 = sign(orient2d(t[1], t[2], p)),
            s2 = sign(orient2d(t[2], t[0], p));
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

bool coplanar_segment_meets_triangle(const Vec3& p, const Vec3& q, const TriangleCorners& t) {
  const Vec3 normal = (t[1] - t[0]).cross(t[2] - t[0]).cwiseAbs();
  int drop = 0;
  normal.maxCoeff(&drop);
  auto project = [drop](const Vec3& v) {
    return drop == 0 ? Vec2(v.y(), v.z()) : drop == 1 ? Vec2(v.x(), v.z()) : Vec2(v.x(), v.y());
  };
  const std::array<Vec2, 3> t2{project(t[0]), project(t[1]), project(t[2])};
  const Vec2 p2 = project(p), q2 = project(q);
  if (inside_triangle_2d(p2, t2) || inside_triangle_2d(q2, t2)) return true;
  for (int e = 0; e < 3; ++e) {
    if (segments_meet_2d(p2, q2, t2[e], t2[(e + 1) % 3])) return true;
  }
  return false;
}

}  // namespace

bool segment_meets_triangle(const Vec3& p, const Vec3& q, const TriangleCorners& t) {
  const int sp = sign(orient3d(t[0], t[1], t[2], p)), sq = sign(orient3d(t[0], t[1], t[2], q));
  if (sp == sq && sp != 0) return false;
  if (sp == 0 && sq == 0) return coplanar_segment_meets_triangle(p, q, t);
  const int s0 = sign(orient3d(p, q, t[0], t[1])), s1 = sign(orient3d(p, q, t[1], t[2])),
            s2 = sign(orient3d(p, q, t[2], t[0]));
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

bool disjoint_triangles_meet(const TriangleCorners& a, const TriangleCorners& b) {
  // Two triangles meet iff an edge of one meets the other (their intersection, when not
  // empty, is a segment or polygon whose boundary lies on the edges of the two).
  for (int e = 0; e < 3; ++e) {
    if (segment_meets_triangle(a[e], a[(e + 1) % 3], b)) return true;
    if (segment_meets_triangle(b[e], b[(e + 1) % 3], a)) return true;
  }
  return false;
}

bool corner_sharing_triangles_overlap(const TriangleCorners& a, const TriangleCorners& b) {
  // Apart from the shared corner, a fold shows as the edge opposite to it crossing the other
  // triangle.
  return segment_meets_triangle(a[1], a[2], b) || segment_meets_triangle(b[1], b[2], a);
}

}  // namespace mrsim
