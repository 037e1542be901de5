#include "meshing/surface_simplifier.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <queue>

#include "meshing/editable_surface.hpp"
#include "meshing/quadric.hpp"

namespace mrsim {
namespace {

struct Collapse {
  double cost = 0.0;
  int keep = 0, drop = 0;  // keep < drop; keep moves to `position`
  unsigned keep_version = 0, drop_version = 0;
  Vec3 position = Vec3::Zero();
};

/// Priority order: lowest cost first, ties by vertex numbers (determinism).
struct LaterFirst {
  bool operator()(const Collapse& a, const Collapse& b) const {
    if (a.cost != b.cost) return a.cost > b.cost;
    return std::pair(a.keep, a.drop) > std::pair(b.keep, b.drop);
  }
};

bool contains(const Triangle& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

std::vector<int> sorted_union(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

/// What a tentative collapse changed, to undo it.
struct Undo {
  std::vector<int> shared;  // the two triangles on the edge, removed
  std::vector<int> fan;     // the triangles that stay around the merged vertex
  std::vector<Triangle> fan_before;
  Vec3 keep_before;
  std::map<int, std::vector<int>> around_before;  // of keep, drop and the two opposite vertices
};

class Simplifier {
 public:
  Simplifier(const SurfaceMesh& surface, const SimplifyOptions& options)
      : surface_(surface, {options.min_triangle_quality, options.max_normal_turn_deg}),
        quadrics_(surface.points.size()), version_(surface.points.size(), 0), options_(options) {
    for (const Triangle& t : surface.triangles) {
      const auto& p = surface.points;
      const Quadric q = Quadric::of_triangle(p[t[0]], p[t[1]], p[t[2]]);
      for (int v : t) quadrics_[v] += q;
    }
  }

  SimplifiedSurface run() {
    std::vector<int> all(quadrics_.size());
    for (int v = 0; v < static_cast<int>(all.size()); ++v) all[v] = v;
    push_edges_of(all);
    std::size_t collapses = 0;
    while (surface_.alive_count() > options_.target_triangles && surface_.alive_count() > 4 && !heap_.empty()) {
      const Collapse c = heap_.top();
      heap_.pop();
      if (try_collapse(c)) ++collapses;
    }
    return {surface_.compacted(), collapses, surface_.alive_count() <= options_.target_triangles};
  }

 private:
  /// Cost: how far the merged point lies from the input triangles it stands for, plus the
  /// squared edge length (short edges first: near-uniform triangles), more so when the new
  /// triangles would be badly shaped.
  std::optional<Collapse> evaluate(int a, int b) const {
    const int keep = std::min(a, b), drop = std::max(a, b);
    const auto& points = surface_.points();
    const Quadric q = quadrics_[keep] + quadrics_[drop];
    const Vec3 p = keep_volume(keep, drop, q.best_point(0.5 * (points[keep] + points[drop])));
    if (!p.allFinite()) return std::nullopt;
    double worst = 1.0;
    for (int v : {keep, drop}) {
      for (int t : surface_.around()[v]) {
        const Triangle& tri = surface_.triangles()[t];
        if (contains(tri, keep) && contains(tri, drop)) continue;
        std::array<Vec3, 3> c;
        for (int k = 0; k < 3; ++k) c[k] = tri[k] == v ? p : points[tri[k]];
        worst = std::min(worst, triangle_quality(c[0], c[1], c[2]));
      }
    }
    const double length2 = (points[keep] - points[drop]).squaredNorm();
    const double cost = q.mean_squared_distance(p) +
                        length2 * (options_.length_weight + options_.shape_weight * (1.0 - worst));
    return Collapse{cost, keep, drop, version_[keep], version_[drop], p};
  }

  /// Moves p along the fan's mean normal until the collapse keeps the enclosed volume
  /// (Lindstrom and Turk's constraint): otherwise coarse surfaces are inscribed and shrink,
  /// and restoring the volume afterwards distorts the boundary tets. The volume is linear in
  /// p: 6 V = sum over the new fan of p . (b x c), with (p, b, c) each triangle from p.
  Vec3 keep_volume(int keep, int drop, const Vec3& p) const {
    const auto& points = surface_.points();
    double six_volume_before = 0.0;
    Vec3 gradient = Vec3::Zero();
    for (int t : sorted_union(surface_.around()[keep], surface_.around()[drop])) {
      const Triangle& tri = surface_.triangles()[t];
      six_volume_before += points[tri[0]].dot(points[tri[1]].cross(points[tri[2]]));
      if (contains(tri, keep) && contains(tri, drop)) continue;
      int k = 0;
      while (tri[k] != keep && tri[k] != drop) ++k;
      gradient += points[tri[(k + 1) % 3]].cross(points[tri[(k + 2) % 3]]);
    }
    const double norm2 = gradient.squaredNorm();
    if (!(norm2 > 0.0)) return p;
    return p + gradient * ((six_volume_before - gradient.dot(p)) / norm2);
  }

  void push_edges_of(const std::vector<int>& vertices) {
    std::vector<std::pair<int, int>> edges;
    for (int v : vertices) {
      for (int w : surface_.ring(v)) edges.emplace_back(std::min(v, w), std::max(v, w));
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& [a, b] : edges) {
      if (auto c = evaluate(a, b)) heap_.push(*c);
    }
  }

  bool try_collapse(const Collapse& c) {
    if (c.keep_version != version_[c.keep] || c.drop_version != version_[c.drop]) return false;
    Undo undo;
    if (!link_condition_holds(c, undo)) return false;
    for (int t : sorted_union(surface_.around()[c.keep], surface_.around()[c.drop])) {
      if (std::find(undo.shared.begin(), undo.shared.end(), t) == undo.shared.end()) undo.fan.push_back(t);
    }
    const EditableSurface::Before before = surface_.snapshot(undo.fan);
    apply(c, undo);
    if (!surface_.acceptable(undo.fan, before)) {
      revert(c, undo);
      return false;
    }
    commit(c, undo);
    return true;
  }

  /// The edge's endpoints share exactly the two opposite vertices of its two triangles:
  /// otherwise the collapse would pinch the surface or close a handle.
  bool link_condition_holds(const Collapse& c, Undo& undo) const {
    for (int t : surface_.around()[c.drop]) {
      if (contains(surface_.triangles()[t], c.keep)) undo.shared.push_back(t);
    }
    if (undo.shared.size() != 2) return false;
    const std::vector<int> a = surface_.ring(c.keep), b = surface_.ring(c.drop);
    std::vector<int> common;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
    return common.size() == 2;
  }

  void apply(const Collapse& c, Undo& undo) {
    auto& around = surface_.around();
    for (int t : undo.shared) {
      for (int v : surface_.triangles()[t]) undo.around_before.try_emplace(v, around[v]);
    }
    for (int t : undo.fan) undo.fan_before.push_back(surface_.triangles()[t]);
    undo.keep_before = surface_.points()[c.keep];
    surface_.points()[c.keep] = c.position;
    for (int t : undo.fan) {
      for (int& v : surface_.triangles()[t]) {
        if (v == c.drop) v = c.keep;
      }
    }
    for (int t : undo.shared) {
      surface_.set_alive(t, false);
      for (int v : surface_.triangles()[t]) {
        around[v].erase(std::remove(around[v].begin(), around[v].end(), t), around[v].end());
      }
    }
    around[c.keep] = undo.fan;
    around[c.drop].clear();
  }

  void revert(const Collapse& c, const Undo& undo) {
    surface_.points()[c.keep] = undo.keep_before;
    for (std::size_t i = 0; i < undo.fan.size(); ++i) surface_.triangles()[undo.fan[i]] = undo.fan_before[i];
    for (int t : undo.shared) surface_.set_alive(t, true);
    for (const auto& [v, list] : undo.around_before) surface_.around()[v] = list;
  }

  void commit(const Collapse& c, const Undo& undo) {
    surface_.changed(undo.fan);
    quadrics_[c.keep] += quadrics_[c.drop];
    ++version_[c.drop];
    // Every edge at the merged vertex's neighbours has a new fan: re-evaluate them.
    std::vector<int> touched = surface_.ring(c.keep);
    touched.push_back(c.keep);
    for (int v : touched) ++version_[v];
    push_edges_of(touched);
  }

  EditableSurface surface_;
  std::vector<Quadric> quadrics_;
  std::vector<unsigned> version_;  // bumped whenever a vertex's collapses change
  std::priority_queue<Collapse, std::vector<Collapse>, LaterFirst> heap_;
  const SimplifyOptions& options_;
};

}  // namespace

SimplifiedSurface simplify_surface(const SurfaceMesh& surface, const SimplifyOptions& options) {
  return Simplifier(surface, options).run();
}

}  // namespace mrsim
