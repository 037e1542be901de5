#include "simulation/level_simulation.hpp"

#include "physics/internal_force.hpp"

namespace mrsim {

HierarchySetup LevelSimulation::one_level(const LevelSetup& setup) {
  HierarchySetup h;
  h.law = setup.law;
  h.gravity = setup.gravity;
  h.integrator = setup.integrator;
  h.dt = setup.dt;
  h.fixed = {setup.fixed};
  h.initial_velocity = setup.initial_velocity;
  h.initial_angular_velocity = setup.initial_angular_velocity;
  return h;
}

LevelSimulation::LevelSimulation(const TetMesh& mesh, const LevelSetup& setup)
    : dt_(setup.dt), sim_({&mesh}, one_level(setup)) {}

double LevelSimulation::elastic_energy() const {
  return mrsim::elastic_energy(model(), state().u.data());
}

}  // namespace mrsim
