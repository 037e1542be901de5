#pragma once
// The elementary per-point updates the integrators are made of (method.md §5.1), over a set of
// points (all, or a level's active points). Fixed points are skipped. No allocation.
#include "core/index_set.hpp"
#include "time/point_state.hpp"

namespace mrsim {

/// v += dt · f / m
void kick(PointState& s, IndexSet points, double dt);
/// v += dt · force / m, with another force array than s.f (Störmer–Verlet's saved force)
void kick(PointState& s, const Vec3* force, IndexSet points, double dt);
/// saved[i] = s.f[i] on `points`
void save_forces(const PointState& s, IndexSet points, Vec3* saved);
/// u += dt · v
void drift(PointState& s, IndexSet points, double dt);
/// Newton–Cotes (two-step midpoint): u ← u_prev + 2dt·v, v ← v_prev + 2dt·f/m, and the (u, v)
/// before the update become u_prev, v_prev. `first`: a modified-Euler step instead (there is no
/// step before).
void two_step_midpoint(PointState& s, IndexSet points, double dt, bool first);

}  // namespace mrsim
