#pragma once
// The largest eigenvalue of M⁻¹A for a level's stiffness (A = K) or damping (A = D) matrix, by
// Lanczos (docs/integrators.md "Calibrated by the spectrum"). The per-point bounds of
// physics/stable_step_bound.hpp are proven but sum a whole star: max_i S_i/m_i is 2.0–2.5 times
// λ_max(M⁻¹K) on the bundled liver levels. That looseness costs √2–√2.5 in an undamped step
// but the full 2–2.5 where damping sets the step. For one global step each level therefore
// scales its point bounds by kSpectralMargin × λ_max / max_i S_i/m_i (never above 1;
// LevelModel's calibrated()): the level alone is estimated within the margin of its true limit,
// and the hierarchy's points keep their relative sizes. Time levels keep the proven bounds.
#include <vector>

#include "core/vec.hpp"
#include "physics/point_adjacency.hpp"

namespace mrsim {

/// Kept between the largest eigenvalue of the linear model at rest and the step: Green–Lagrange
/// stiffens in tension (+32 % in ω² at 10 % stretch), and the hierarchy couples levels through
/// ghosts whose bounds are not calibrated. 1.5 in ω² is 1.22 in the undamped step.
inline constexpr double kSpectralMargin = 1.5;

/// λ_max of M^-1/2 A M^-1/2, where (A u)_i = Σ_j A_ij (u_j − u_i) over the CSR edge blocks of
/// `adj` (the sign convention of LevelModel::K and ::D; A positive semi-definite), free
/// boundary (fixed points only lower it). Lanczos from a fixed start vector (deterministic),
/// until the Ritz value's residual bound is below `tolerance` of it or after `max_iterations`;
/// returns the Ritz value plus that residual bound, so that it errs upwards. 0 for an empty
/// level or A = 0.
double largest_mass_scaled_eigenvalue(const PointAdjacency& adj, const std::vector<Mat3>& edge,
                                      const std::vector<double>& mass, double tolerance = 1e-3,
                                      int max_iterations = 300);

/// How a level's tet bounds are scaled (stiffness or damping).
struct SpectralScale {
  double eigenvalue = 0;  // λ_max(M⁻¹A), 1/s² (stiffness) or 1/s (damping)
  double star_max = 0;    // max_i of the point bound over the mass, same unit
  double scale = 1;       // min(1, kSpectralMargin × eigenvalue / star_max)
};

SpectralScale spectral_scale(double eigenvalue, double star_max);

}  // namespace mrsim
