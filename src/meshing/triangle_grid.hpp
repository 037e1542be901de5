#pragma once
// A spatial hash of triangles for the simplifier's intersection queries, where triangles
// change shape as edges collapse. A changed triangle is simply inserted again: stale entries
// stay in their cells and are filtered by the caller (alive flag, exact test), and the grid is
// rebuilt with larger cells as the triangles grow.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/vec.hpp"

namespace mrsim {

struct BoundingBox {
  Vec3 lo, hi;
  bool overlaps(const BoundingBox& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
};

class TriangleGrid {
 public:
  explicit TriangleGrid(double cell = 1.0) : cell_(cell) {}

  void insert(const BoundingBox& box, int triangle);

  /// Every triangle inserted into a cell that `box` touches, each once, in no fixed order.
  void query(const BoundingBox& box, std::vector<int>& out);

 private:
  template <typename Visit>
  void for_cells(const BoundingBox& box, Visit visit) const;

  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::vector<unsigned> seen_;  // per triangle: the query stamp that reported it last
  unsigned stamp_ = 0;
};

}  // namespace mrsim
