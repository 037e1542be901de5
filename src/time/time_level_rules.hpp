#pragma once
// How a particle chooses its time level k, dt_k = frame_dt / 2^k (method.md §5.2):
//   - stability: dt_k <= C × the particle's stable-step estimate (physics/stable_step_bound.hpp:
//     its level, the stiffness and mass reaching it through ghosts, contact, damping; doubled
//     elastic part for the semi-implicit step), C = time.courant; updated at every topology
//     change;
//   - velocity change, dynamic: δ = |Δv| dt_k / h = |f| dt_k² / (m h). Above β the particle goes
//     one level finer at once; below β/4 over a whole frame (δ ∝ dt², so that is "below β one
//     level coarser") it goes one level coarser at the next frame boundary, never below its
//     Courant level.
#include <cstdint>
#include <vector>

#include "core/vec.hpp"
#include "physics/level_model.hpp"

namespace mrsim {

struct TimeLevelRules {
  double frame_dt = 0.04;         // s
  int max_level = 0;              // finest allowed level: frame_dt / 2^max_level is the finest step
  double courant = 1.0;           // C, the fraction of the stable-step estimate used
  double velocity_change = 0.01;  // β, dimensionless
  bool semi_implicit = false;     // the elastic part of the estimate doubled
};

/// The coarsest time level whose step frame_dt / 2^k is within C × `stable` (s), capped at
/// rules.max_level (a point that cannot meet it gets max_level; the stable-step check warns).
int stable_time_level(const TimeLevelRules& rules, double stable);

/// stable_time_level of every point of a level alone (whole stars, calibrated() for time levels, no
/// contact).
std::vector<std::int8_t> courant_levels(const LevelModel& model, const TimeLevelRules& rules);

/// δ of method.md §5.2 for a particle with force f, inverse mass, step dt and edge h.
inline double velocity_change(const Vec3& f, double inv_mass, double dt, double h) {
  return f.norm() * inv_mass * dt * dt / h;
}

}  // namespace mrsim
