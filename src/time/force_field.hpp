#pragma once
// What an integrator needs from the physics: the total force on the points it integrates.
// One virtual call per evaluation (never per point).
#include <cstdint>

#include "core/vec.hpp"

namespace mrsim {

class ForceField {
 public:
  virtual ~ForceField() = default;
  /// Overwrites f with internal + external forces at state (u, v) on the points this field
  /// serves; returns how many point forces it evaluated (the work counter of product.md).
  virtual std::int64_t evaluate(const Vec3* u, const Vec3* v, Vec3* f) = 0;
};

}  // namespace mrsim
