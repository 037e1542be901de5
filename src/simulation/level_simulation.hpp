#pragma once
// One mesh level with every point active (issue 2): precomputed model, state, force field and
// integrator. The multiresolution hierarchy (issue 4) will drive several of these.
#include <cstdint>
#include <memory>

#include "physics/level_model.hpp"
#include "simulation/level_force_field.hpp"
#include "time/stepper.hpp"

namespace mrsim {

struct LevelSetup {
  MaterialLaw law;
  Vec3 gravity = Vec3::Zero();
  Integrator integrator = Integrator::ModifiedEuler;
  double dt = 1e-3;                        // s, step
  std::vector<std::uint8_t> fixed;         // 1 = Dirichlet point; empty = none
  Vec3 initial_velocity = Vec3::Zero();    // m/s
  Vec3 initial_angular_velocity = Vec3::Zero();  // rad/s about the centre of mass
};

class LevelSimulation {
 public:
  LevelSimulation(const TetMesh& mesh, const LevelSetup& setup);
  /// Advances `steps` steps of the setup's dt.
  void advance(int steps);

  const LevelModel& model() const { return model_; }
  const PointState& state() const { return state_; }
  PointState& state() { return state_; }
  double dt() const { return dt_; }
  std::int64_t force_evaluations() const { return stepper_->force_evaluations(0); }
  double elastic_energy() const;

 private:
  void set_initial_velocity(const LevelSetup& setup);
  LevelModel model_;
  PointState state_;
  double dt_;
  std::unique_ptr<LevelForceField> forces_;
  std::unique_ptr<Stepper> stepper_;
};

}  // namespace mrsim
