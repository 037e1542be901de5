#pragma once
// Interface mass consistent with interface stiffness (docs/hierarchy.md "Interface mass").
// Under the energy couplings a tet that a level simulates with weight w (its active share, or
// the patch-test weight) contributes w of its strain energy, and its forces reach the level's
// active points and ghosts, the ghosts' then passed to their sources. Its mass follows the
// same path, or a ghost that coincides with an active point of another level hands that point
// a whole tet star's stiffness without the matching mass (nested levels then blow up at their
// own stable step). So each tet gives w ρV/4 to each of its four vertices, and a ghost with
// interpolation weights b passes b_k² of its mass to source k: the diagonal of its consistent
// mass Jᵀ m J, exact for a ghost that coincides with a source (b = 1). Row sums (b_k, the
// total kept) put whole coarse stars on the four tiny vertices of a child tet (130 times their
// own mass on the liver levels), whose relative motion the ghost does not even see: slow
// spurious modes kept liver_press refining. What b² leaves, (1 − Σ b_k²) of the ghost's mass,
// goes back to the active vertices of the tets that gave it, on the ghost's own level, so the
// inertial mass is the simulated volume's, as gravity's is. b² alone kept 0.946 of it on a
// small box with many interfaces, whose centre of mass then fell at g / 0.946, and lost 2–3 %
// of a mixed beam's near its free end: that beam vibrated 3.4 % faster than either level
// alone. Gravity uses the mass passed on with b (the gradient of
// the potential energy, total kept). The energy bounds of stiffness and damping
// (physics/stable_step_bound.hpp) go straight to the active points along the ghost's whole row
// c (the chain of ghosts composed), point k taking a_k Σ_j c_j²/a_j of them with a_k =
// m_k √|c_k| (Cauchy–Schwarz: |Σ c u|² ≤ Σ c²/a Σ a |u|² for any a > 0), so every active point
// knows the stable step of what it carries.
#include <cstdint>
#include <vector>

#include "hierarchy/merged_rows.hpp"
#include "hierarchy/status_lists.hpp"
#include "physics/level_model.hpp"

namespace mrsim {

struct InertiaLevel {
  const LevelModel* model = nullptr;
  const std::vector<int>* tets = nullptr;       // live tets (read when weighted)
  const std::vector<double>* weight = nullptr;  // per tet; nullptr: no ghosts, whole stars
  const std::vector<std::uint8_t>* free_point = nullptr;  // fixed ghosts pass nothing on
};

/// out[l][p] for the active points of every level: the star's own values where the level has
/// no ghosts (bit for bit the lumped mass), the weighted and transferred values otherwise.
/// Ghost entries are left as scratch. `transfer`: the energy couplings (ghosts pass their share
/// on); without it (the thesis' force coupling) every active point keeps its own star.
/// O(active + live tets + the ghosts' merged rows). `rows`: scratch for those rows, cleared here;
/// kept by the caller from one topology change to the next, its memory is allocated once (a
/// fresh one regrew hundreds of kilobytes of terms at every change, fragmenting the heap).
void interface_inertia(const Hierarchy& h, const StatusLists& lists,
                       const std::vector<InertiaLevel>& levels, bool transfer,
                       std::vector<std::vector<PointInertia>>& out, MergedRows& rows);

}  // namespace mrsim
