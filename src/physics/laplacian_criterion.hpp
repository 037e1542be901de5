#pragma once
// The split/merge quality indicator of method.md §3: c_i = h_i ‖(Δu)_i‖ with the
// boundary-corrected Laplacian L^c_i = -Σ_t V_t (G_t - Ḡ_i) ∇N_i^t, (Δu)_i = L^c_i / V*_i.
// Zero for every linear displacement field (hence for any rigid motion), interior or boundary.
#include <span>
#include <vector>

#include "physics/level_model.hpp"

namespace mrsim {

/// Boundary-corrected discrete Laplacian of u at point i (m^-1), i.e. L^c_i / V*_i.
Vec3 corrected_laplacian(const LevelModel& model, int i, const Vec3* u);

/// The gradients of a level's live tets, computed once for all the points that share them.
struct TetGradientCache {
  std::vector<int> slot;  // per tet of the level: its entry in G, or -1
  std::vector<Mat3> G;
};

/// c_i = mean_edge_i ‖corrected_laplacian(i)‖ into criterion[i] for each of `points`, every tet
/// around them in `tets` (sorted: the live tets of `points`, internal_force.hpp live_tets()).
/// Each tet's gradient is computed once, not once per vertex: the same bits as
/// corrected_laplacian() point by point. O(|tets| + incidences of `points`).
void corrected_criterion(const LevelModel& model, std::span<const int> points,
                         std::span<const int> tets, const Vec3* u, TetGradientCache& cache,
                         double* criterion);

/// c_i for every point of the level (dimensionless), into `criterion`.
void laplacian_criterion(const LevelModel& model, const Vec3* u, std::vector<double>& criterion);

}  // namespace mrsim
