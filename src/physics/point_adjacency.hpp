#pragma once
// Point-centred connectivity in CSR form. Every force is a per-point *gather* over these lists
// (product.md determinism: results do not depend on the thread count, no atomics, no scatter).
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

struct PointAdjacency {
  // Edge neighbours N(i) (method.md §2.2), sorted ascending: nbr[nbr_start[i] .. nbr_start[i+1]).
  std::vector<int> nbr_start, nbr;
  // Incident tets of i with i's local index in each: inc_tet / inc_local over inc_start.
  std::vector<int> inc_start, inc_tet;
  std::vector<std::int8_t> inc_local;

  int num_points() const { return static_cast<int>(nbr_start.size()) - 1; }
  int degree(int i) const { return nbr_start[i + 1] - nbr_start[i]; }
};

PointAdjacency build_point_adjacency(int num_points, const std::vector<Tet>& tets);

/// Index of the CSR entry (i, j) in `nbr`, or -1 if j is not a neighbour of i.
int find_neighbour_entry(const PointAdjacency& adj, int i, int j);

}  // namespace mrsim
