#include "simulation/level_force_field.hpp"
#include "core/parallel.hpp"

namespace mrsim {

LevelForceField::LevelForceField(const LevelModel& model, const Vec3& gravity) : model_(model) {
  weight_.resize(model.num_points());
  for (int i = 0; i < model.num_points(); ++i) weight_[i] = model.mass[i] * gravity;
  ws_.reserve_for(model);
}

void LevelForceField::evaluate(const Vec3* u, const Vec3* v, Vec3* f) {
  internal_forces(model_, u, v, f, ws_);
  const int n = model_.num_points();
#pragma omp parallel for schedule(static) if (n >= parallel_threshold())
  for (int i = 0; i < n; ++i) f[i] += weight_[i];
}

}  // namespace mrsim
