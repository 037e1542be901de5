#include "simulation/level_force_field.hpp"

#include "core/parallel.hpp"

namespace mrsim {

LevelForceField::LevelForceField(const LevelModel& model, const Vec3& gravity) : model_(model) {
  weight_.resize(model.num_points());
  for (int i = 0; i < model.num_points(); ++i) weight_[i] = model.mass[i] * gravity;
  tet_mark_.assign(model.num_tets(), 0);
  ws_.reserve_for(model);
}

void LevelForceField::serve(const std::vector<int>* points) {
  points_ = points;
  refresh_tets();
}

void LevelForceField::refresh_tets() {
  if (points_ && model_.law.strain == StrainMeasure::GreenLagrange)
    live_tets(model_, IndexSet::of(*points_), tet_mark_, tets_);
}

IndexSet LevelForceField::points() const {
  return points_ ? IndexSet::of(*points_) : IndexSet::all(model_.num_points());
}

std::int64_t LevelForceField::evaluate(const Vec3* u, const Vec3* v, Vec3* f) {
  const IndexSet pts = points();
  const IndexSet tets = points_ ? IndexSet::of(tets_) : IndexSet::all(model_.num_tets());
  internal_forces(model_, pts, tets, u, v, f, ws_);
  const int n = pts.count;
#pragma omp parallel for schedule(static) if (n >= parallel_threshold())
  for (int k = 0; k < n; ++k) f[pts[k]] += weight_[pts[k]];
  return n;
}

}  // namespace mrsim
