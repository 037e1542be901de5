#pragma once
// Advances the points of one level by one step of the chosen scheme (method.md §5.1, §5.3).
// Exactly one force evaluation per step for every scheme.
#include <cstdint>

#include "time/force_field.hpp"
#include "time/integrator_kind.hpp"
#include "time/point_state.hpp"
#include "time/semi_implicit_filter.hpp"

namespace mrsim {

class LevelIntegrator {
 public:
  /// `filter` is used by SemiImplicit only (built for the step dt).
  LevelIntegrator(Integrator kind, ForceField& forces, SemiImplicitFilter filter = {});

  /// Must be called once before the first step (Störmer–Verlet needs f at t = 0).
  void start(PointState& s);
  void step(PointState& s, double dt);
  std::int64_t force_evaluations() const { return evaluations_; }
  Integrator kind() const { return kind_; }

 private:
  void evaluate(PointState& s);
  Integrator kind_;
  ForceField& forces_;
  SemiImplicitFilter filter_;
  std::int64_t evaluations_ = 0;
};

}  // namespace mrsim
