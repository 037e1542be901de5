#include "meshing/editable_surface.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "meshing/self_intersection.hpp"

namespace mrsim {
namespace {

// Edge neighbours whose normals are closer to opposite than this have folded onto each other
// (a turn of more than ~154 degrees); the exact intersection test does not see that case.
constexpr double kFoldCosine = -0.9;

bool contains(const Triangle& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

}  // namespace

double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  if (squares == 0.0) return 0.0;
  return 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / squares;
}

EditableSurface::EditableSurface(const SurfaceMesh& surface, const EditLimits& limits)
    : points_(surface.points), triangles_(surface.triangles), alive_(triangles_.size(), 1),
      around_(points_.size()), alive_count_(triangles_.size()), limits_(limits),
      cos_turn_(std::cos(limits.max_normal_turn_deg * std::numbers::pi / 180.0)) {
  for (int t = 0; t < static_cast<int>(triangles_.size()); ++t) {
    for (int v : triangles_[t]) around_[v].push_back(t);
  }
  rebuild_grid();
}

void EditableSurface::set_alive(int t, bool alive) {
  if ((alive_[t] != 0) == alive) return;
  alive_[t] = alive;
  alive ? ++alive_count_ : --alive_count_;
}

std::vector<int> EditableSurface::ring(int v) const {
  std::vector<int> r;
  for (int t : around_[v]) {
    for (int w : triangles_[t]) {
      if (w != v) r.push_back(w);
    }
  }
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

int EditableSurface::across(int t, int a, int b) const {
  for (int s : around_[a]) {
    if (s != t && alive_[s] && contains(triangles_[s], b)) return s;
  }
  return -1;
}

Vec3 EditableSurface::unit_normal(int t) const {
  const Triangle& tri = triangles_[t];
  return (points_[tri[1]] - points_[tri[0]]).cross(points_[tri[2]] - points_[tri[0]]).normalized();
}

double EditableSurface::quality(int t) const {
  const Triangle& tri = triangles_[t];
  return triangle_quality(points_[tri[0]], points_[tri[1]], points_[tri[2]]);
}

EditableSurface::Before EditableSurface::snapshot(const std::vector<int>& triangles) const {
  Before before;
  for (int t : triangles) {
    before.normals.push_back(unit_normal(t));
    before.worst_quality = std::min(before.worst_quality, quality(t));
  }
  return before;
}

bool EditableSurface::acceptable(const std::vector<int>& changed, const Before& before) {
  return shapes_acceptable(changed, before) && no_folds(changed) && no_intersections(changed);
}

bool EditableSurface::shapes_acceptable(const std::vector<int>& changed, const Before& before) const {
  const double floor = std::min(limits_.min_triangle_quality, before.worst_quality);
  for (std::size_t i = 0; i < changed.size(); ++i) {
    const Vec3 n = unit_normal(changed[i]);
    if (!n.allFinite() || n.dot(before.normals[i]) < cos_turn_) return false;
    if (quality(changed[i]) < floor) return false;
  }
  return true;
}

bool EditableSurface::no_folds(const std::vector<int>& changed) const {
  for (int t : changed) {
    const Triangle& tri = triangles_[t];
    const Vec3 n = unit_normal(t);
    for (int e = 0; e < 3; ++e) {
      const int s = across(t, tri[e], tri[(e + 1) % 3]);
      if (s < 0 || n.dot(unit_normal(s)) < kFoldCosine) return false;
    }
  }
  return true;
}

bool EditableSurface::no_intersections(const std::vector<int>& changed) {
  for (int t : changed) {
    const BoundingBox box = box_of(t);
    // A changed triangle keeps at least one corner, so its stale grid entries are found too.
    grid_.query(box, nearby_);
    for (int s : nearby_) {
      if (s == t || !alive_[s] || !box.overlaps(box_of(s))) continue;
      if (triangles_meet(points_, triangles_[t], triangles_[s])) return false;
    }
  }
  return true;
}

void EditableSurface::changed(const std::vector<int>& triangles) {
  for (int t : triangles) grid_.insert(box_of(t), t);
  // Triangles grow as the surface coarsens: larger cells keep the queries short.
  if (2 * alive_count_ <= grid_built_for_) rebuild_grid();
}

BoundingBox EditableSurface::box_of(int t) const {
  const Triangle& tri = triangles_[t];
  BoundingBox b{points_[tri[0]], points_[tri[0]]};
  for (int v : tri) b.lo = b.lo.cwiseMin(points_[v]), b.hi = b.hi.cwiseMax(points_[v]);
  return b;
}

void EditableSurface::rebuild_grid() {
  double length = 0.0;
  std::size_t edges = 0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    if (!alive_[t]) continue;
    for (int e = 0; e < 3; ++e) length += (points_[triangles_[t][e]] - points_[triangles_[t][(e + 1) % 3]]).norm();
    edges += 3;
  }
  grid_ = TriangleGrid(edges && length > 0.0 ? length / static_cast<double>(edges) : 1.0);
  for (int t = 0; t < static_cast<int>(triangles_.size()); ++t) {
    if (alive_[t]) grid_.insert(box_of(t), t);
  }
  grid_built_for_ = alive_count_;
}

SurfaceMesh EditableSurface::compacted() const {
  SurfaceMesh out;
  std::vector<int> index(points_.size(), -1);
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    if (!alive_[t]) continue;
    Triangle tri = triangles_[t];
    for (int& v : tri) {
      if (index[v] < 0) index[v] = static_cast<int>(out.points.size()), out.points.push_back(points_[v]);
      v = index[v];
    }
    out.triangles.push_back(tri);
    out.face_of.push_back(static_cast<int>(out.triangles.size()));
  }
  return out;
}

}  // namespace mrsim
