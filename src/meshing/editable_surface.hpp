#pragma once
// A closed triangulated surface being edited in place (edge collapses, edge flips, vertex
// moves) with the checks every edit must pass to keep it a valid boundary for a tet mesher:
// no triangle flipped, turned too far or badly shaped, no two edge neighbours folded onto each
// other, no triangle meeting another (self_intersection.hpp's exact test through a spatial
// hash). Edits are made tentatively by the caller, checked with acceptable(), then either
// kept (changed()) or undone by the caller. Triangle numbers never change; removed triangles
// are marked dead.
#include <vector>

#include "meshing/surface_mesh.hpp"
#include "meshing/triangle_grid.hpp"

namespace mrsim {

struct EditLimits {
  double min_triangle_quality = 0.2;  // unless no worse than the worst triangle replaced
  double max_normal_turn_deg = 60.0;  // per edit, per triangle
};

class EditableSurface {
 public:
  EditableSurface(const SurfaceMesh& surface, const EditLimits& limits);

  std::vector<Vec3>& points() { return points_; }
  const std::vector<Vec3>& points() const { return points_; }
  std::vector<Triangle>& triangles() { return triangles_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// Alive triangles at each vertex, sorted; the editor keeps these lists up to date.
  std::vector<std::vector<int>>& around() { return around_; }
  const std::vector<std::vector<int>>& around() const { return around_; }
  bool alive(int t) const { return alive_[t] != 0; }
  void set_alive(int t, bool alive);
  std::size_t alive_count() const { return alive_count_; }

  /// Neighbour vertices of v, sorted.
  std::vector<int> ring(int v) const;
  /// The alive triangle other than t on the edge (a, b), or -1.
  int across(int t, int a, int b) const;
  Vec3 unit_normal(int t) const;
  double quality(int t) const;

  /// Unit normals and worst quality of triangles, taken before an edit.
  struct Before {
    std::vector<Vec3> normals;
    double worst_quality = 1.0;
  };
  Before snapshot(const std::vector<int>& triangles) const;

  /// Checks the triangles changed by a tentative edit (same order as `before`).
  bool acceptable(const std::vector<int>& changed, const Before& before);

  /// Records that the kept edit changed these triangles (re-indexes them for the checks).
  void changed(const std::vector<int>& triangles);

  /// The alive triangles with points renumbered in order of first use; face_of = 1..n.
  SurfaceMesh compacted() const;

 private:
  bool shapes_acceptable(const std::vector<int>& changed, const Before& before) const;
  bool no_folds(const std::vector<int>& changed) const;
  bool no_intersections(const std::vector<int>& changed);
  BoundingBox box_of(int t) const;
  void rebuild_grid();

  std::vector<Vec3> points_;
  std::vector<Triangle> triangles_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> around_;
  std::size_t alive_count_ = 0;
  EditLimits limits_;
  double cos_turn_;
  TriangleGrid grid_;
  std::size_t grid_built_for_ = 0;
  std::vector<int> nearby_;
};

/// 4 sqrt(3) area / (sum of squared edge lengths): 1 for an equilateral triangle, 0 if flat.
double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace mrsim
