#include "simulation/hierarchical_simulation.hpp"

#include <algorithm>

#include "hierarchy/ghost_force_transfer.hpp"
#include "simulation/diagnostics.hpp"

namespace mrsim {

HierarchicalSimulation::HierarchicalSimulation(const std::vector<const TetMesh*>& meshes,
                                               const HierarchySetup& setup) {
  const int L = static_cast<int>(meshes.size());
  coupling_ = setup.coupling;
  transfer_ = coupling_ == Coupling::Energy && L > 1;  // one level: no ghost, nothing to send
  std::vector<HierarchyLevel> levels;
  for (int l = 0; l < L; ++l) {
    models_.push_back(std::make_unique<LevelModel>(build_level_model(*meshes[l], setup.law)));
    levels.push_back({meshes[l], &models_[l]->adj});
  }
  hierarchy_ = std::make_unique<Hierarchy>(levels, build_level_links(levels));
  lists_ = std::make_unique<StatusLists>(*hierarchy_);
  states_.resize(L);
  stale_.resize(L);
  std::vector<IntegrationBlock> blocks(L);
  for (int l = 0; l < L; ++l) {
    PointState& s = states_[l];
    s.resize(models_[l]->num_points());
    for (int i = 0; i < s.size(); ++i) s.inv_mass[i] = 1.0 / models_[l]->mass[i];
    if (l < static_cast<int>(setup.fixed.size()) && !setup.fixed[l].empty())
      for (int i = 0; i < s.size(); ++i) s.free_point[i] = setup.fixed[l][i] ? 0 : 1;
    stale_[l].assign(s.size(), 0);
    const Vec3 c = centre_of_mass(*models_[0]->mesh, models_[0]->mass);
    for (int i = 0; i < s.size(); ++i)
      if (s.free_point[i])
        s.v[i] = setup.initial_velocity +
                 setup.initial_angular_velocity.cross(meshes[l]->points[i] - c);
    forces_.push_back(std::make_unique<LevelForceField>(*models_[l], setup.gravity));
    if (transfer_)
      forces_[l]->couple(hierarchy_.get(), lists_.get(), l);
    else
      forces_[l]->serve(&lists_->active(l));
    blocks[l].state = &s;
    blocks[l].forces = forces_[l].get();
    blocks[l].points = &lists_->active(l);
    if (setup.integrator == Integrator::SemiImplicit)
      blocks[l].filter = SemiImplicitFilter(*models_[l], s.inv_mass, setup.dt);
    fields_.push_back({s.u.data(), s.v.data()});
    level_forces_.push_back(s.f.data());
  }
  std::function<void()> gathered;
  if (transfer_)
    gathered = [this] { transfer_ghost_forces(*hierarchy_, *lists_, level_forces_); };
  stepper_ = std::make_unique<Stepper>(setup.integrator, std::move(blocks),
                                       [this] { refresh_ghosts(); }, std::move(gathered));
  dt_ = setup.dt;
  stepper_->start();
}

void HierarchicalSimulation::advance(int steps) {
  for (int s = 0; s < steps; ++s) stepper_->step(dt_);
}

void HierarchicalSimulation::refresh_ghosts() { update_ghosts(*hierarchy_, *lists_, fields_); }

void HierarchicalSimulation::compute_forces() {
  for (int l = 0; l < num_levels(); ++l)
    forces_[l]->evaluate(states_[l].u.data(), states_[l].v.data(), states_[l].f.data());
  if (transfer_) transfer_ghost_forces(*hierarchy_, *lists_, level_forces_);
}

void HierarchicalSimulation::split(int level, int point) {
  for (const auto& w : hierarchy_->split(level, point)) {
    woken_.push_back(w);
    stale_[w.first][w.second] = 1;
  }
}

void HierarchicalSimulation::merge(int level, int point) { hierarchy_->merge(level, point); }

// The current value of a point that may not be simulated: its own if it is up to date,
// otherwise interpolated from its parent tet, recursively (level 0 is always up to date).
Vec3 HierarchicalSimulation::fresh_value(int l, int q, bool velocity) const {
  const bool own = l == 0 || (!stale_[l][q] && hierarchy_->state(l, q) != NodeState::Inactive);
  if (own) return velocity ? states_[l].v[q] : states_[l].u[q];
  const auto& emb = hierarchy_->links(l).parent_tet;
  const Tet& t = models_[l - 1]->mesh->tets[emb.tet[q]];
  Vec3 x = Vec3::Zero();
  for (int a = 0; a < 4; ++a) x += emb.bary[q][a] * fresh_value(l - 1, t[a], velocity);
  return x;
}

void HierarchicalSimulation::apply_changes() {
  lists_->update(*hierarchy_, hierarchy_->take_touched());
  // Coarse to fine, so a woken point's sources are initialised before it.
  std::sort(woken_.begin(), woken_.end());
  for (const auto& [l, q] : woken_) {
    if (!stale_[l][q]) continue;
    stale_[l][q] = 0;
    if (!states_[l].free_point[q]) continue;  // Dirichlet points stay at rest
    const Vec3 u = fresh_value(l, q, false), v = fresh_value(l, q, true);
    states_[l].u[q] = u;
    states_[l].v[q] = v;
  }
  woken_.clear();
  for (auto& f : forces_) f->refresh_tets();
  refresh_ghosts();
  stepper_->start();
}

void HierarchicalSimulation::fill_inactive() { interpolate_inactive(*hierarchy_, fields_); }

}  // namespace mrsim
