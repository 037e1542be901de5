#pragma once
// What an integrator needs from the physics: the total force on every point for a given state.
// One virtual call per evaluation (never per point).
#include "core/vec.hpp"

namespace mrsim {

class ForceField {
 public:
  virtual ~ForceField() = default;
  /// f = internal + external forces at state (u, v); overwrites f for every point.
  virtual void evaluate(const Vec3* u, const Vec3* v, Vec3* f) = 0;
};

}  // namespace mrsim
