#pragma once
// The row of the interpolation map for one point: the active points that move it and their
// weights (method.md §4.1, §4.8). A subdivided ghost follows its child tet, an interface ghost or
// an inactive point its parent tet, recursively, until active points are reached. A point held
// by the support (fixed and not active) ends the recursion with level -1: it does not move and a
// force on it goes to the support. The transpose of the same row carries a force on the point to
// the active points, so the virtual work of a load or a contact force matches the motion shown.
#include <cstdint>
#include <vector>

#include "hierarchy/hierarchy.hpp"

namespace mrsim {

struct ActiveTerm {
  int level = 0;  // -1: held by the support
  int point = 0;  // point of `level` (for the support: the fixed point's own index)
  double weight = 0;
};

/// Appends weight × (row of point p of level l) to `out`; `free_point[l][p]` is 0 for
/// Dirichlet points. Terms are not merged (the same active point may appear several times).
void append_active_row(const Hierarchy& h,
                       const std::vector<const std::vector<std::uint8_t>*>& free_point, int l,
                       int p, double weight, std::vector<ActiveTerm>& out);

}  // namespace mrsim
