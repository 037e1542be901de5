#pragma once
// Point location in a tet mesh (method.md §4.3 step 1): the tet that contains a point, with its
// barycentric coordinates, or — for points outside the mesh, near the boundary of independent
// meshes of one object — the nearest tet with signed coordinates (one or more negative), so
// that ghost interpolation extrapolates (§4.1 point 6). Uniform grid over tet bounding boxes:
// O(T) to build, O(1) expected per query.
#include <array>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

struct TetLocation {
  int tet = -1;
  std::array<double, 4> bary{};  // Σ = 1; all ≥ 0 (up to rounding) when inside
  double distance = 0;           // m, 0 when inside
  bool inside() const { return distance == 0; }
};

class TetLocator {
 public:
  explicit TetLocator(const TetMesh& mesh);
  TetLocation locate(const Vec3& p) const;
  /// The tet holding p with the largest smallest barycentric coordinate (ties: lowest index), or
  /// -1 when p is outside; no search for the nearest tet. locate() answers with it inside.
  int containing(const Vec3& p) const;
  /// The same answer, trying `hint` first (a tet near p, or -1): when p is inside it by a clear
  /// margin no other tet of a mesh whose tets do not overlap can hold p better, so the cell's
  /// other tets are not tested. For runs of nearby queries (the level ownership's samples).
  /// With the mesh's face neighbours (mesh/tet_neighbours.hpp), a walk from the hint across the
  /// face p lies farthest beyond, until a tet holds p by that margin.
  int containing(const Vec3& p, int hint,
                 const std::vector<std::array<int, 4>>* neighbours = nullptr) const;
  /// Barycentric coordinates of p in tet t (signed).
  std::array<double, 4> barycentric(int t, const Vec3& p) const;
  const TetMesh& mesh() const { return mesh_; }

 private:
  int cell_index(int i, int j, int k) const { return i + dims_[0] * (j + dims_[1] * k); }
  std::array<int, 3> cell_of(const Vec3& p) const;
  /// 0 when b (p's barycentric coordinates in t) is inside, else the distance to t.
  double distance_to_tet(int t, const Vec3& p, const std::array<double, 4>& b) const;
  /// Distance from p to t's bounding box: a lower bound of its distance.
  double box_gap(int t, const Vec3& p) const;
  /// Distance from p (barycentric coordinates b in t) to the farthest plane of t's faces that
  /// p is beyond: another lower bound of its distance, and a tight one when the nearest point
  /// lies inside a face.
  double plane_gap(int t, const std::array<double, 4>& b) const;
  void consider(int t, double gap, const Vec3& p, TetLocation& best, double& best_key) const;

  /// A tet's bounding box grown by 1e-6 of its extent: a point whose barycentric coordinates
  /// are all ≥ −ε lies within the box grown by 3ε of it (p = Σ b_k x_k, Σ b_k = 1), so the box
  /// keeps every tet that can hold a point, with room for the coordinates' rounding; its gap to
  /// a point is a lower bound of the tet's distance.
  struct Box {
    Vec3 lo, hi;
  };

  const TetMesh& mesh_;
  std::vector<Mat3> inverse_;  // D_t^{-1}, for barycentrics
  std::vector<Box> box_;       // one cache line per tet tested, both corners together
  Vec3 lo_;
  double h_ = 1;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> cell_start_, cell_tets_;
};

}  // namespace mrsim
