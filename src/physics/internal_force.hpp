#pragma once
// Elastic + strain-rate damping forces of one level (method.md §2.2–2.3), computed as per-point
// gathers (or, on one thread, per-tet additions in the same order) so the result is
// bit-identical for any thread count.
//   Cauchy: f_i = -Σ_j K_ij (u_j - u_i) - Σ_j D_ij (v_j - v_i)     (edge matrices, §2.2)
//   Green:  f_a = -Σ_{t∋a} V_t F_t (S_t + 𝒱_t) ∇N_a                (per-tet pass, then gather)
#include <vector>

#include "core/index_set.hpp"
#include "physics/level_model.hpp"
#include "physics/packed_tets.hpp"

namespace mrsim {

/// Scratch memory reused across steps (no allocation in the step loop).
struct ForceWorkspace {
  std::vector<TetGradients> tet_force;  // -V P ∇N_a per tet and vertex (stored pass, Cauchy)
  std::vector<int> all_tets;             // 0 .. tets-1, when a pass covers every tet
  std::vector<unsigned char> point_mask; // the points a pass writes (zero between calls)
  std::vector<std::vector<int>> thread_tets;  // each thread's tets (threaded Green pass)
  // A tet list's data copied contiguously (its owner packs it at topology changes): the
  // one-thread Green–Lagrange pass over that list reads the copy (physics/packed_tets.hpp).
  PackedTets packed;
  /// Sizes the arrays for `model`; the per-tet forces only with `per_tet`.
  void reserve_for(const LevelModel& model, bool per_tet = false);
};

/// f[i] = internal force on every point i of the level (overwrites f).
void internal_forces(const LevelModel& model, const Vec3* u, const Vec3* v, Vec3* f,
                     ForceWorkspace& ws);

/// Internal forces on `points` only (overwrites f there, leaves the rest). Green needs the
/// per-tet pass on every tet incident to those points: `tets` must contain them all
/// (see live_tets()); Cauchy ignores it. Cost O(points + tets).
void internal_forces(const LevelModel& model, IndexSet points, IndexSet tets, const Vec3* u,
                     const Vec3* v, Vec3* f, ForceWorkspace& ws);

/// Forces of a level the hierarchy simulates only in part (energy-consistent coupling,
/// docs/hierarchy.md): f[i] = Σ_{t∋i} tet_weight[t] × (nodal force of t on i), for `points`
/// (active points and ghosts). `tets` must hold every tet with a non-zero weight; other tets are
/// skipped. Same stress as internal_forces() for both strain measures. Cost O(points + tets).
void weighted_internal_forces(const LevelModel& model, IndexSet points, IndexSet tets,
                              const double* tet_weight, const Vec3* u, const Vec3* v, Vec3* f,
                              ForceWorkspace& ws);

/// Tets incident to at least one of `points`, ascending, using `mark` (one byte per tet, all
/// zero on entry and on return) to deduplicate. O(Σ incident tets).
void live_tets(const LevelModel& model, IndexSet points, std::vector<unsigned char>& mark,
               std::vector<int>& out);

/// Internal force on one point from its incident tets only (used by the Jacobian probe of the
/// semi-implicit step, method.md §5.3). Equal to internal_forces()[i] up to rounding.
Vec3 point_internal_force(const LevelModel& model, int i, const Vec3* u, const Vec3* v);

/// Strain energy Σ_t V_t W(E_t) with the level's strain measure (J). Fixed summation order.
double elastic_energy(const LevelModel& model, const Vec3* u);

}  // namespace mrsim
