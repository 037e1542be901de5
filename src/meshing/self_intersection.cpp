#include "meshing/self_intersection.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "meshing/triangle_intersection.hpp"

namespace mrsim {
namespace {

constexpr std::size_t kExamples = 3;

struct Box {
  Vec3 lo, hi;
  bool overlaps(const Box& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
};

Box triangle_box(const SurfaceMesh& s, const Triangle& t) {
  Box b{s.points[t[0]], s.points[t[0]]};
  for (int v : t) {
    b.lo = b.lo.cwiseMin(s.points[v]);
    b.hi = b.hi.cwiseMax(s.points[v]);
  }
  return b;
}

class Grid {
 public:
  Grid(const Box& bounds, std::size_t items) : origin_(bounds.lo) {
    // About one triangle per cell on average: cells of the size of a typical triangle.
    const Vec3 extent = (bounds.hi - bounds.lo).cwiseMax(1e-300);
    const double cell_volume = extent.prod() / static_cast<double>(std::max<std::size_t>(items, 1));
    cell_ = std::max(std::cbrt(cell_volume), extent.maxCoeff() / 256.0);
    for (int d = 0; d < 3; ++d) dims_[d] = std::clamp(static_cast<int>(extent[d] / cell_) + 1, 1, 256);
    cells_.resize(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2]);
  }

  std::array<int, 3> cell_of(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d) c[d] = std::clamp(static_cast<int>((p[d] - origin_[d]) / cell_), 0, dims_[d] - 1);
    return c;
  }

  void insert(const Box& box, int item) {
    const auto lo = cell_of(box.lo), hi = cell_of(box.hi);
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int k = lo[2]; k <= hi[2]; ++k) cells_[index({i, j, k})].push_back(item);
  }

  std::size_t index(const std::array<int, 3>& c) const {
    return (static_cast<std::size_t>(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
  }
  const std::vector<std::vector<int>>& cells() const { return cells_; }

 private:
  Vec3 origin_;
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::vector<int>> cells_;
};

int shared_vertices(const Triangle& a, const Triangle& b) {
  int shared = 0;
  for (int u : a) shared += std::count(b.begin(), b.end(), u) > 0;
  return shared;
}

/// Corners of t rotated so that `first` comes first (it keeps the triangle's orientation).
TriangleCorners corners_from(const std::vector<Vec3>& points, const Triangle& t, int first) {
  int k = 0;
  while (t[k] != first) ++k;
  return {points[t[k]], points[t[(k + 1) % 3]], points[t[(k + 2) % 3]]};
}

}  // namespace

bool triangles_meet(const std::vector<Vec3>& points, const Triangle& a, const Triangle& b) {
  switch (shared_vertices(a, b)) {
    case 0:
      return disjoint_triangles_meet(corners_from(points, a, a[0]), corners_from(points, b, b[0]));
    case 1: {
      int common = a[0];
      for (int u : a) {
        if (std::count(b.begin(), b.end(), u) > 0) common = u;
      }
      return corner_sharing_triangles_overlap(corners_from(points, a, common), corners_from(points, b, common));
    }
    case 2:
      return false;  // edge neighbours: folds there are caught by the orientation check
    default:
      return true;   // the same triangle twice
  }
}

SelfIntersections find_self_intersections(const SurfaceMesh& surface) {
  const int n = static_cast<int>(surface.triangles.size());
  std::vector<Box> boxes(n);
  Box bounds{surface.points.front(), surface.points.front()};
  for (int t = 0; t < n; ++t) {
    boxes[t] = triangle_box(surface, surface.triangles[t]);
    bounds.lo = bounds.lo.cwiseMin(boxes[t].lo);
    bounds.hi = bounds.hi.cwiseMax(boxes[t].hi);
  }
  Grid grid(bounds, static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t) grid.insert(boxes[t], t);
  SelfIntersections found;
  for (std::size_t c = 0; c < grid.cells().size(); ++c) {
    const auto& items = grid.cells()[c];
    for (std::size_t x = 0; x < items.size(); ++x) {
      for (std::size_t y = x + 1; y < items.size(); ++y) {
        const int i = std::min(items[x], items[y]), j = std::max(items[x], items[y]);
        if (!boxes[i].overlaps(boxes[j])) continue;
        // Test each pair once: in the cell holding the low corner of the boxes' overlap.
        if (grid.index(grid.cell_of(boxes[i].lo.cwiseMax(boxes[j].lo))) != c) continue;
        if (!triangles_meet(surface.points, surface.triangles[i], surface.triangles[j])) continue;
        if (found.pairs++ < kExamples) found.first.emplace_back(i, j);
      }
    }
  }
  std::sort(found.first.begin(), found.first.end());
  return found;
}

}  // namespace mrsim
