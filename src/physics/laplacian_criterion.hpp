#pragma once
// The split/merge quality indicator of method.md §3: c_i = h_i ‖(Δu)_i‖ with the
// boundary-corrected Laplacian L^c_i = -Σ_t V_t (G_t - Ḡ_i) ∇N_i^t, (Δu)_i = L^c_i / V*_i.
// Zero for every linear displacement field (hence for any rigid motion), interior or boundary.
#include <vector>

#include "physics/level_model.hpp"

namespace mrsim {

/// Boundary-corrected discrete Laplacian of u at point i (m^-1), i.e. L^c_i / V*_i.
Vec3 corrected_laplacian(const LevelModel& model, int i, const Vec3* u);

/// c_i for every point of the level (dimensionless), into `criterion`.
void laplacian_criterion(const LevelModel& model, const Vec3* u, std::vector<double>& criterion);

}  // namespace mrsim
