#include "meshing/tet_quality.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "mesh/boundary_faces.hpp"

namespace mrsim {
namespace {

// Vertex pairs of the six edges, each followed by the two other vertices (the edge's faces).
constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                              {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};

struct TetShape {
  double min_dihedral, max_dihedral, radius_ratio, volume;
};

double dihedral_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Angle along edge ab between faces abc and abd: the angle between the components of ac
  // and ad orthogonal to ab.
  const Vec3 axis = (b - a).normalized();
  const Vec3 u = (c - a) - axis * axis.dot(c - a);
  const Vec3 v = (d - a) - axis * axis.dot(d - a);
  const double cosine = std::clamp(u.dot(v) / (u.norm() * v.norm()), -1.0, 1.0);
  return std::acos(cosine) * 180.0 / std::numbers::pi;
}

double face_area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

TetShape tet_shape(const std::array<Vec3, 4>& p) {
  TetShape s{180.0, 0.0, 0.0, 0.0};
  for (const auto& e : kEdges) {
    const double angle = dihedral_deg(p[e[0]], p[e[1]], p[e[2]], p[e[3]]);
    s.min_dihedral = std::min(s.min_dihedral, angle);
    s.max_dihedral = std::max(s.max_dihedral, angle);
  }
  const Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  s.volume = a.dot(b.cross(c)) / 6.0;
  const double area = face_area(p[0], p[1], p[2]) + face_area(p[0], p[1], p[3]) +
                      face_area(p[0], p[2], p[3]) + face_area(p[1], p[2], p[3]);
  const double r_in = 3.0 * s.volume / area;
  const double r_circ =
      (a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b)).norm() /
      (12.0 * s.volume);
  s.radius_ratio = std::clamp(3.0 * r_in / r_circ, 0.0, 1.0);
  return s;
}

void edge_statistics(const TetMesh& mesh, TetQuality& q) {
  std::set<std::pair<int, int>> edges;
  for (const Tet& t : mesh.tets) {
    for (const auto& e : kEdges) edges.insert(std::minmax(t[e[0]], t[e[1]]));
  }
  double sum = 0.0;
  q.min_edge = INFINITY;
  q.max_edge = 0.0;
  for (const auto& [i, j] : edges) {
    const double length = (mesh.points[i] - mesh.points[j]).norm();
    sum += length;
    q.min_edge = std::min(q.min_edge, length);
    q.max_edge = std::max(q.max_edge, length);
  }
  q.mean_edge = edges.empty() ? 0.0 : sum / static_cast<double>(edges.size());
}

}  // namespace

TetQuality measure_quality(const TetMesh& mesh) {
  TetQuality q;
  q.points = mesh.points.size();
  q.tets = mesh.tets.size();
  q.min_dihedral_deg = 180.0;
  q.min_radius_ratio = 1.0;
  double ratio_sum = 0.0;
  for (const Tet& t : mesh.tets) {
    const TetShape s = tet_shape({mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]});
    q.min_dihedral_deg = std::min(q.min_dihedral_deg, s.min_dihedral);
    q.max_dihedral_deg = std::max(q.max_dihedral_deg, s.max_dihedral);
    q.min_radius_ratio = std::min(q.min_radius_ratio, s.radius_ratio);
    ratio_sum += s.radius_ratio;
    q.volume += s.volume;
    const int bin = std::min(kRadiusRatioBins - 1, static_cast<int>(s.radius_ratio * kRadiusRatioBins));
    ++q.radius_ratio_histogram[bin];
  }
  q.mean_radius_ratio = mesh.tets.empty() ? 0.0 : ratio_sum / static_cast<double>(mesh.tets.size());
  edge_statistics(mesh, q);
  q.boundary_triangles = boundary_faces(mesh).size();
  return q;
}

bool better_quality(const TetQuality& a, const TetQuality& b) {
  if (a.min_dihedral_deg != b.min_dihedral_deg) return a.min_dihedral_deg > b.min_dihedral_deg;
  return a.mean_radius_ratio > b.mean_radius_ratio;
}

}  // namespace mrsim
