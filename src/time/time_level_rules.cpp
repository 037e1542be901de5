#include "time/time_level_rules.hpp"

namespace mrsim {

int stable_time_level(const TimeLevelRules& rules, double stable) {
  const double allowed = rules.courant * stable;
  int k = 0;
  while (k < rules.max_level && rules.frame_dt / (1 << k) > allowed) ++k;
  return k;
}

std::vector<std::int8_t> courant_levels(const LevelModel& model, const TimeLevelRules& rules) {
  std::vector<std::int8_t> level(model.num_points(), 0);
  for (int i = 0; i < model.num_points(); ++i) {
    const PointInertia p = calibrated(model.star[i], model, rules.semi_implicit, true, 0.0, 0.0, i);
    level[i] = static_cast<std::int8_t>(
        stable_time_level(rules, stable_step_of(p, rules.semi_implicit)));
  }
  return level;
}

}  // namespace mrsim
