#pragma once
// How a particle chooses its time level k, dt_k = frame_dt / 2^k (method.md §5.2):
//   - Courant, static: dt_k <= C × (shortest rest edge at the particle) / c_p, c_p the P-wave
//     speed, C doubled for the semi-implicit step (it doubles the usable step, §5.3);
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
  double frame_dt = 0.04;        // s
  int max_level = 0;             // finest allowed level: frame_dt / 2^max_level is the finest step
  double courant = 0.5;          // C, dimensionless
  double velocity_change = 0.01; // β, dimensionless
  bool semi_implicit = false;    // Courant bound doubled
};

/// The Courant bound C × h / c_p of an edge h (s), doubled for the semi-implicit step: the one
/// stable-step estimate of the project (per particle here, per level in stable_step.hpp).
inline double courant_step(const MaterialLaw& law, double courant, bool semi_implicit, double h) {
  return (semi_implicit ? 2.0 : 1.0) * courant * h / law.p_wave_speed();
}

/// The coarsest level whose step meets the Courant bound at each point of the level, capped
/// at rules.max_level (a point that cannot meet it gets max_level; the scenario check warns).
std::vector<std::int8_t> courant_levels(const LevelModel& model, const TimeLevelRules& rules);

/// δ of method.md §5.2 for a particle with force f, inverse mass, step dt and edge h.
inline double velocity_change(const Vec3& f, double inv_mass, double dt, double h) {
  return f.norm() * inv_mass * dt * dt / h;
}

}  // namespace mrsim
