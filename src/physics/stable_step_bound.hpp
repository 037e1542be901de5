#pragma once
// The stable step of an explicit particle, from bounds that a point can compute alone
// (method.md §5.2; docs/integrators.md "The stable step"). Energy (Rayleigh) bound: a tet's
// strain energy under any displacement u is at most ½ d_t Σ_a |u_a|², with
//   d_t = V_t (λ |G|_F² + 2μ σ_max(G)²),  G = [∇N_0 … ∇N_3] (3×4),
// because 2E = V (λ tr(ε)² + 2μ |ε|²), tr ε = ⟨U, G⟩ ≤ |U| |G|_F and |ε| ≤ |U Gᵀ| ≤ σ_max |U|.
// Summing over the tets a point carries (with their energy-coupling weights, and what reaches
// it through ghosts, hierarchy/interface_inertia.hpp) gives its share S_i, and every
// eigenvalue of M⁻¹K lies below max_i S_i / m_i: ω_i² = S_i / m_i is the point's own bound.
// Damping (Kelvin–Voigt, φ/ψ of eq. 2.22) has the same form with φ, ψ in place of λ, μ.
//
// A kick–drift step of ẍ + γẋ + ω²x = 0 with the damping force explicit is stable for
//   dt ≤ (√(γ² + 4ω²) − γ) / ω² = 4 / (γ + √(γ² + 4ω²)) = (2/ω)(√(1+ζ²) − ζ),  ζ = γ/(2ω).
// The semi-implicit filter (eq. 5.1) treats the elastic part implicitly: the thesis' doubled
// step, 4 / (γ + √(γ² + ω²)), and the damping limit 2/γ stays.
#include <vector>

#include "physics/material_law.hpp"
#include "physics/point_adjacency.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

/// Per tet: d_t of the elastic stiffness at rest (N/m; the Cauchy matrix of §2.2, also
/// Green–Lagrange's tangent at rest) and of the damping (N·s/m).
struct TetEnergyBounds {
  std::vector<double> stiffness, damping;
};

TetEnergyBounds tet_energy_bounds(const TetGeometry& geo, const MaterialLaw& law);

/// Mass, stiffness bound and damping bound of one point: what its stable step depends on; and
/// the mass gravity pulls on (kg), which differs from the inertial mass at level interfaces
/// (hierarchy/interface_inertia.hpp).
struct PointInertia {
  double mass = 0, stiffness = 0, damping = 0;
  double gravity_mass = 0;
  double contact_stiffness = 0;  // N/m of tool penalty: explicit for every integrator
};

/// The uncalibrated semi-implicit rule: the elastic ω² counts a quarter, the thesis' doubled
/// step. Calibrated (one global step) the elastic part is the filtered spectrum instead
/// (physics/spectral_bound.hpp, filter_scale()); the contact penalty always counts in full.
inline constexpr double kSemiImplicitShare = 0.25;

/// Σ over the tets of each point (whole stars, every weight 1), mass = lumped mass.
std::vector<PointInertia> star_inertia(const PointAdjacency& adj, const TetEnergyBounds& tets,
                                       const std::vector<double>& mass);

/// The largest stable step of a point (s): the smallest root of dt²ω² + 2dt γ = 4 with
/// ω² = (share × stiffness + contact) / m, share 1 or kSemiImplicitShare; +inf when there is
/// none (no stiffness and no damping, or a negative calibrated semi-implicit stiffness).
double stable_step_of(const PointInertia& p, bool semi_implicit);

/// Newton–Cotes (the two-step midpoint rule) is stable up to dt = 1/ω undamped: this share of
/// the kick–drift limit 2/ω. With any damping its parasitic root grows at every step size, so
/// its estimate is the kick–drift one halved, a scale rather than a guarantee.
inline constexpr double kTwoStepMidpointShare = 0.5;

}  // namespace mrsim
