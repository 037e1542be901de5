#pragma once
// Lumped (barycentric) masses m_i = ρ Σ_{t∋i} V_t / 4 (method.md §2.4).
#include <vector>

#include "physics/point_adjacency.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

std::vector<double> lumped_masses(const TetGeometry& geo, const PointAdjacency& adj, double density);

}  // namespace mrsim
