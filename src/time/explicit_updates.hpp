#pragma once
// The elementary per-point updates the integrators are made of (method.md §5.1), over a set of
// points (all, or a level's active points). Fixed points are skipped. No allocation.
#include "core/index_set.hpp"
#include "time/point_state.hpp"

namespace mrsim {

/// v += dt · f / m
void kick(PointState& s, IndexSet points, double dt);
/// u += dt · v
void drift(PointState& s, IndexSet points, double dt);

}  // namespace mrsim
