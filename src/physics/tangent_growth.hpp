#pragma once
// How far a Green–Lagrange tet's tangent stiffness has grown beyond the rest stiffness that the
// stable-step bounds are built from (physics/stable_step_bound.hpp; docs/integrators.md "The
// stable step"). With F = I + ∇u, E = ½(FᵀF − I) and S = λ tr(E) I + 2μE, a displacement δu
// changes the stress by δP = δF S + F (λ tr(δE) I + 2μ δE), δE = sym(Fᵀ δF). Its energy
// δF:δP is at most
//   material part:  σ_max(F)² times the rest bound d_t (δE ≤ σ_max(F) δF, term by term), and
//   geometric part: max(0, s_max(S)) |δF|² ≤ max(0, s_max(S)) / (λ + 2μ) × d_t,
// since d_t ≥ V (λ + 2μ) σ_max(∇N)². So the tangent is below (1 + g) d_t with
//   g = σ_max(F)² − 1 + max(0, s_max(S)) / (λ + 2μ) = 2 e_max + max(0, λ tr E + 2μ e_max)/(λ+2μ),
// e_max the largest eigenvalue of E; clamped at 0 (compression softens). A rigid motion has
// g = 0: rotation alone never shortens a step.
// The strain-rate damping grows too (method.md §1 and §2.3: eq. 2.22 on Ė = sym(Fᵀ Ḟ)): its stress
// F (φ tr(Ė) I + 2ψ Ė) changes with the velocity by F 𝒱(sym(Fᵀ δḞ)), whose energy rate is at most
// σ_max(F)² times the rest damping bound, the material part alone: g_d = σ_max(F)² − 1 = 2 e_max,
// clamped at 0. (Its change with the position is proportional to the strain rate and is not
// counted.)
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "physics/material_law.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

/// g of one tet with displacement gradient `grad_u`, with the law's bounding λ and μ under the
/// tet's scales `s` (MaterialLaw::bound_lambda/bound_mu on a calibrated level).
double tangent_growth(const Mat3& grad_u, const MaterialLaw& law, const StiffnessScales& s);
inline double tangent_growth(const Mat3& grad_u, const MaterialLaw& law) {
  return tangent_growth(grad_u, law, law.scales);
}

/// The largest g over `tets` of a level at displacements `u`; 0 for an empty list.
double largest_tangent_growth(const TetGeometry& geo, std::span<const int> tets,
                              const std::vector<Vec3>& u, const MaterialLaw& law);

/// g_d of one tet: how far its damping tangent has grown, 2 e_max clamped at 0.
double damping_growth(const Mat3& grad_u);

/// Growths that need not be exact: a tet whose g and g_d are provably at most these (a
/// Gershgorin bound on e_max, a few flops) reports that bound instead of solving for e_max.
/// The explicit schemes count none at or below (kSpectralMargin − 1, √kSpectralMargin − 1)
/// (physics/spectral_bound.hpp explicit_stiffening()); {0, 0}: always exact.
struct GrowthsNeeded {
  double stiffness_above = 0, damping_above = 0;
};

/// The largest g over `tets` (largest_tangent_growth()), and per point of those tets the
/// largest g and the largest g_d among the listed tets it belongs to, into stiffness[point] and
/// damping[point] (only those points are written; one entry per point of the level). With
/// `needed`, values at or below its thresholds may be upper bounds (above them, exact).
double tangent_growths_of(const TetGeometry& geo, std::span<const int> tets,
                          const std::vector<Vec3>& u, const MaterialLaw& law,
                          std::vector<double>& stiffness, std::vector<double>& damping,
                          GrowthsNeeded needed = {});

}  // namespace mrsim
