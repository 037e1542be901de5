#pragma once
// The elementary per-point updates the integrators are made of (method.md §5.1). Fixed points
// are skipped. Each is a plain parallel loop over points: no allocation.
#include "time/point_state.hpp"

namespace mrsim {

/// v += dt · f / m
void kick(PointState& s, double dt);
/// u += dt · v
void drift(PointState& s, double dt);

}  // namespace mrsim
