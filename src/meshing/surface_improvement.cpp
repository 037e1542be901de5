#include "meshing/surface_improvement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "meshing/editable_surface.hpp"

namespace mrsim {
namespace {

constexpr double kMinGain = 1e-3;  // an edit must raise the worst quality by this much

void insert_sorted(std::vector<int>& list, int t) { list.insert(std::lower_bound(list.begin(), list.end(), t), t); }
void erase_one(std::vector<int>& list, int t) { list.erase(std::remove(list.begin(), list.end(), t), list.end()); }

int third_corner(const Triangle& t, int a, int b) {
  for (int v : t) {
    if (v != a && v != b) return v;
  }
  return -1;
}

class Improver {
 public:
  Improver(const SurfaceMesh& surface, const ImproveOptions& options)
      : surface_(surface, {0.0, options.max_move_turn_deg}),
        options_(options) {}

  SurfaceMesh run() {
    for (int round = 0; round < options_.rounds; ++round) {
      int edits = 0;
      for (int t = 0; t < static_cast<int>(surface_.triangles().size()); ++t) {
        for (int e = 0; e < 3 && surface_.alive(t); ++e) edits += try_flip(t, e);
      }
      for (int v = 0; v < static_cast<int>(surface_.points().size()); ++v) edits += try_move(v);
      if (edits == 0) break;
    }
    return surface_.compacted();
  }

 private:
  /// The flip replaces the surface between a, b, c, d by the other diagonal: allowed where
  /// the two diagonals nearly meet, so the shape barely changes. (A normals test would refuse
  /// to flip exactly the needle and cap triangles whose normals are noisy.)
  bool nearly_flat(int a, int b, int c, int d) const {
    const auto& p = surface_.points();
    const Vec3 ab = p[b] - p[a], cd = p[d] - p[c];
    const double across = ab.cross(cd).norm();
    if (across == 0.0) return false;
    const double gap = std::abs((p[c] - p[a]).dot(ab.cross(cd))) / across;  // between the lines
    return gap <= options_.max_flip_gap * std::min(ab.norm(), cd.norm());
  }

  /// Flips the edge from corner e of t to the next corner, if it helps.
  bool try_flip(int t1, int e) {
    const Triangle tri = surface_.triangles()[t1];
    const int a = tri[e], b = tri[(e + 1) % 3], c = tri[(e + 2) % 3];
    if (a > b) return false;  // each edge once per pass
    const int t2 = surface_.across(t1, a, b);
    if (t2 < 0) return false;
    const int d = third_corner(surface_.triangles()[t2], a, b);
    auto& around = surface_.around();
    if (around[a].size() <= 3 || around[b].size() <= 3) return false;
    const std::vector<int> ring_c = surface_.ring(c);
    if (std::binary_search(ring_c.begin(), ring_c.end(), d)) return false;  // c-d exists already
    if (!nearly_flat(a, b, c, d)) return false;
    // Delaunay flip: the angles opposite the edge sum to more than pi. Such edges make the
    // tet mesher put a flat tet on the two triangles.
    const auto& p = surface_.points();
    auto angle = [&p](int apex, int x, int y) {
      const Vec3 u = (p[x] - p[apex]).normalized(), w = (p[y] - p[apex]).normalized();
      return std::acos(std::clamp(u.dot(w), -1.0, 1.0));
    };
    const bool delaunay = angle(c, a, b) + angle(d, a, b) > std::numbers::pi + kMinGain;
    if (!delaunay) return false;
    const EditableSurface::Before before = surface_.snapshot({t1, t2});
    const Triangle old1 = tri, old2 = surface_.triangles()[t2];
    // (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c): same orientation.
    surface_.triangles()[t1] = {c, a, d};
    surface_.triangles()[t2] = {d, b, c};
    erase_one(around[b], t1), erase_one(around[a], t2), insert_sorted(around[c], t2), insert_sorted(around[d], t1);
    if (delaunay && surface_.acceptable({t1, t2}, before)) {
      surface_.changed({t1, t2});
      return true;
    }
    surface_.triangles()[t1] = old1;
    surface_.triangles()[t2] = old2;
    insert_sorted(around[b], t1), insert_sorted(around[a], t2), erase_one(around[c], t2), erase_one(around[d], t1);
    return false;
  }

  /// Moves v towards its neighbours' centroid within its tangent plane, if it helps.
  bool try_move(int v) {
    const std::vector<int> fan = surface_.around()[v];
    if (fan.empty()) return false;
    auto& points = surface_.points();
    Vec3 normal = Vec3::Zero(), centroid = Vec3::Zero();
    for (int t : fan) {
      const Triangle& tri = surface_.triangles()[t];
      normal += (points[tri[1]] - points[tri[0]]).cross(points[tri[2]] - points[tri[0]]);
    }
    const std::vector<int> ring = surface_.ring(v);
    for (int w : ring) centroid += points[w];
    centroid /= static_cast<double>(ring.size());
    normal.normalize();
    const Vec3 old = points[v];
    const Vec3 step = (centroid - old) - normal * normal.dot(centroid - old);
    const EditableSurface::Before before = surface_.snapshot(fan);
    points[v] = old + step;
    double worst = 1.0;
    for (int t : fan) worst = std::min(worst, surface_.quality(t));
    if (normal.allFinite() && worst > before.worst_quality + kMinGain && surface_.acceptable(fan, before)) {
      surface_.changed(fan);
      return true;
    }
    points[v] = old;
    return false;
  }

  EditableSurface surface_;
  const ImproveOptions& options_;
};

}  // namespace

SurfaceMesh improve_triangle_shapes(const SurfaceMesh& surface, const ImproveOptions& options) {
  return Improver(surface, options).run();
}

}  // namespace mrsim
