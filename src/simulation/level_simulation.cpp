#include "simulation/level_simulation.hpp"

#include "physics/internal_force.hpp"
#include "simulation/diagnostics.hpp"

namespace mrsim {

LevelSimulation::LevelSimulation(const TetMesh& mesh, const LevelSetup& setup)
    : model_(build_level_model(mesh, setup.law)), dt_(setup.dt) {
  const int n = model_.num_points();
  state_.resize(n);
  for (int i = 0; i < n; ++i) state_.inv_mass[i] = 1.0 / model_.mass[i];
  if (!setup.fixed.empty())
    for (int i = 0; i < n; ++i) state_.free_point[i] = setup.fixed[i] ? 0 : 1;
  set_initial_velocity(setup);
  forces_ = std::make_unique<LevelForceField>(model_, setup.gravity);
  SemiImplicitFilter filter;
  if (setup.integrator == Integrator::SemiImplicit)
    filter = SemiImplicitFilter(model_, state_.inv_mass, dt_);
  std::vector<IntegrationBlock> blocks(1);
  blocks[0].state = &state_;
  blocks[0].forces = forces_.get();
  blocks[0].filter = std::move(filter);
  stepper_ = std::make_unique<Stepper>(setup.integrator, std::move(blocks));
  stepper_->start();
}

void LevelSimulation::set_initial_velocity(const LevelSetup& setup) {
  const Vec3 c = centre_of_mass(*model_.mesh, model_.mass);
  for (int i = 0; i < state_.size(); ++i)
    if (state_.free_point[i])
      state_.v[i] = setup.initial_velocity +
                    setup.initial_angular_velocity.cross(model_.mesh->points[i] - c);
}

void LevelSimulation::advance(int steps) {
  for (int s = 0; s < steps; ++s) stepper_->step(dt_);
}

double LevelSimulation::elastic_energy() const {
  return mrsim::elastic_energy(model_, state_.u.data());
}

}  // namespace mrsim
