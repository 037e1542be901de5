#pragma once
// Local loads of the per-tet calibration (hierarchy/level_calibration.hpp, docs/hierarchy.md
// "Per-tet tensors"): a tool or a press acts on a few finest surface points, and in the
// hierarchy their forces reach a coarse level through the barycentric weights of those points
// in its tets (ghost force transfer, method.md §4.1). So each load is a unit force spread
// evenly over the finest level's free boundary points within `radius` of a centre, pushing
// inwards; a coarse level receives it through its located weights, and its compliance fᵀK⁻¹f
// is compared with the finest level's own. Centres: the highest free boundary point, then each
// next the one farthest from those chosen.
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

struct LocalLoad {
  std::vector<int> points;  // finest boundary points, not held
  Vec3 force;               // N on each of them (their sum is a unit force)
};

/// Up to `count` loads (fewer when the free boundary has fewer points).
std::vector<LocalLoad> local_loads(const TetMesh& finest, const std::vector<std::uint8_t>& fixed,
                                   int count, double radius);

/// Forces at the finest level's points (3 per point) as nodal forces of `level` (3 per point,
/// fixed points included): each point's force spread on the tet of `level` that holds it (or the
/// nearest, extrapolated) by its barycentric weights, as the hierarchy transfers a ghost's force
/// (method.md §4.1). On the finest level itself, the forces as given.
std::vector<Eigen::VectorXd> to_level(const std::vector<Eigen::VectorXd>& fine_forces,
                                      const TetMesh& finest, const TetMesh& level);

/// Each load as forces at the finest level's points (3 per point).
std::vector<Eigen::VectorXd> point_forces(const std::vector<LocalLoad>& loads,
                                          const TetMesh& finest);

/// Each load as nodal forces of `level` (3 per point, fixed points included): each finest
/// point's force spread on the tet of `level` that holds it (or the nearest, extrapolated), by
/// its barycentric weights. On the finest level itself, the forces at its points.
std::vector<Eigen::VectorXd> level_loads(const std::vector<LocalLoad>& loads,
                                         const TetMesh& finest, const TetMesh& level);

}  // namespace mrsim
