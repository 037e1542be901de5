#pragma once
// Semi-implicit time levels: what the filter leaves explicit, point by point. The filtered
// operator M^-1/2 (K − 2 blockdiag K) M^-1/2 (physics/spectral_bound.hpp) restricted to the
// one-ring patch of each point (the point and its neighbours, the rest held) has a largest
// eigenvalue L_p that a point can compute alone; its highest modes live at the scale of a tet,
// so the patches find 0.6–0.9 of the level's λ_f on the bundled livers (the global λ_f is the
// largest over any set of points, so it is never below them). Each point counts of its proven
// stiffness bound the share kSpectralMargin × max(L over the patches it belongs to) × m_i / S_i,
// between kFilterStiffening and the thesis' kSemiImplicitShare: a slab of tiny tets gets its
// own share, which a level's uniform one did not (docs/integrators.md "The stable step").
#include <vector>

#include "core/vec.hpp"
#include "physics/point_adjacency.hpp"
#include "physics/stable_step_bound.hpp"

namespace mrsim {

/// L_p for every point: the largest eigenvalue of the filtered operator on its one-ring patch
/// (held points, mass infinite, left out); -inf for a held point or one with no free patch.
std::vector<double> patch_filtered_eigenvalues(const PointAdjacency& adj,
                                               const std::vector<Mat3>& edge,
                                               const std::vector<double>& mass);

/// Each point's share of its proven stiffness bound (above), from its star and the patches'
/// L_p; kSemiImplicitShare where a star has no stiffness.
std::vector<double> time_level_filter_shares(const PointAdjacency& adj,
                                             const std::vector<double>& patch_eigenvalue,
                                             const std::vector<PointInertia>& star);

/// No point's share below the level's: kSpectralMargin × λ_f over the level's largest point
/// bound, as the one global step counts (physics/spectral_bound.hpp filter_scale()), so that the
/// largest point's ω² covers the level's filtered spectrum also where the patches miss its top
/// mode (one that spans many patches: on a jittered box at λ = 5·10⁴, μ = 10⁴ the patches'
/// shares alone counted 0.79 of λ_f). No effect when λ_f ≤ 0 or no point has a bound.
void raise_to_level_share(std::vector<double>& share, double filtered, double star_max);

}  // namespace mrsim
