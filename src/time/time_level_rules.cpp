#include "time/time_level_rules.hpp"

namespace mrsim {

std::vector<std::int8_t> courant_levels(const LevelModel& model, const TimeLevelRules& rules) {
  std::vector<std::int8_t> level(model.num_points(), 0);
  for (int i = 0; i < model.num_points(); ++i) {
    const double allowed =
        courant_step(model.law, rules.courant, rules.semi_implicit, model.min_edge[i]);
    int k = 0;
    while (k < rules.max_level && rules.frame_dt / (1 << k) > allowed) ++k;
    level[i] = static_cast<std::int8_t>(k);
  }
  return level;
}

}  // namespace mrsim
